# An existing output or log is never replaced without --force, and a refusal leaves both alone.
DAMAGE=$(dirname "$TAPE")/tape-damage
echo keep > worn.ptp
echo keep > worn.jsonl
$DAMAGE tapes/16k20f3s5-turning.iso.ptp -o worn.ptp --seed 1 --flips 0.1; echo "exit $?"
$DAMAGE tapes/16k20f3s5-turning.iso.ptp -o new.ptp --seed 1 --flips 0.1 --log worn.jsonl; echo "exit $?"
ls; cat worn.ptp worn.jsonl
$DAMAGE tapes/16k20f3s5-turning.iso.ptp -o worn.ptp --seed 1 --flips 0.1 --log worn.jsonl --force; echo "exit $?"
cmp -s worn.ptp tapes/16k20f3s5-turning.iso.ptp || echo "worn.ptp replaced by a damaged read"
wc -l < worn.jsonl
