# Usage errors end 2 and write nothing: no seed, rates outside 0..1 or adding up to more than 1, more torn
# than the data spans, a leader that is no number, an output format that cannot be written, both outputs on stdout.
DAMAGE=$(dirname "$TAPE")/tape-damage
in=tapes/16k20f3s5-turning.iso.ptp
$DAMAGE $in -o out.ptp; echo "exit $?"
$DAMAGE $in -o out.ptp --seed 1 --flips 1.5; echo "exit $?"
$DAMAGE $in -o out.ptp --seed 1 --drops -0.1; echo "exit $?"
$DAMAGE $in -o out.ptp --seed 1 --damage nan; echo "exit $?"
$DAMAGE $in -o out.ptp --seed 1 --flips 0.6 --drops 0.6; echo "exit $?"
$DAMAGE $in -o out.ptp --seed 1 --torn 1000; echo "exit $?"
$DAMAGE $in -o out.ptp --seed 1 --leader ten; echo "exit $?"
$DAMAGE $in -o out.ptp --seed 1 --burst-length 0; echo "exit $?"
$DAMAGE $in -o out.hex --seed 1 --format hex; echo "exit $?"
$DAMAGE $in -o - --seed 1 --log -; echo "exit $?"
$DAMAGE missing.ptp -o out.ptp --seed 1; echo "exit $?"
ls
