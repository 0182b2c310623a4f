# tape-damage: a seed gives the same damaged read every time; the log (frames from 1) says what was done,
# and decoding the read finds parity errors at the frames the log names (read_frame).
DAMAGE=$(dirname "$TAPE")/tape-damage
$DAMAGE tapes/16k20f3s5-turning.iso.ptp -o worn.ptp --seed 1 --damage 0.05 --log worn.jsonl; echo "exit $?"
cat worn.jsonl
$DAMAGE tapes/16k20f3s5-turning.iso.ptp -o again.ptp --seed 1 --damage 0.05 && cmp worn.ptp again.ptp && echo "same read for the same seed"
$DAMAGE tapes/16k20f3s5-turning.iso.ptp -o other.ptp --seed 2 --damage 0.05 && ! cmp -s worn.ptp other.ptp && echo "another read for another seed"
$TAPE decode -k worn.ptp -o worn.txt; echo "exit $?"
