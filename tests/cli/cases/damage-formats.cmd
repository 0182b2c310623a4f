# Any image in, OUT in the format of its extension or --format; a holes picture names the characters in
# the code of the undamaged tape, so that garbled frames stand out. A 5-track image stays 5-track.
DAMAGE=$(dirname "$TAPE")/tape-damage
$DAMAGE tapes/16k20f3s5-turning.iso.ptp -o worn.holes --seed 3 --bursts 0.02 --burst-length 3 --log - &&
  sed -n '86,93p' worn.holes
$DAMAGE worn.holes -o - --format holes --seed 4 --start-late 100 --stop-early 305 --flips 0.5 --log flips.jsonl
cat flips.jsonl
$DAMAGE tapes/telegram.mtk2.hex5 -o worn.hex5 --seed 9 --flips 0.2 --bursts 0.05 --log - | grep -c .
$TAPE decode --code mtk2 worn.hex5 >/dev/null && echo "worn.hex5 reads as a 5-track image"
