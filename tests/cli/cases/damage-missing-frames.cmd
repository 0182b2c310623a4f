# Frames missing from the read: a torn-out piece inside the data, leader cut (never into the data), a reader
# that starts late and stops early; drops and doubles change the length by what the log says.
DAMAGE=$(dirname "$TAPE")/tape-damage
$TAPE info tapes/16k20f3s5-turning.iso.ptp | sed -n '/^frames:/,/^  trailer:/p'
$DAMAGE tapes/16k20f3s5-turning.iso.ptp -o torn.ptp --seed 5 --torn 10 --leader -60 --start-late 20 --stop-early 30 --log -
$TAPE info torn.ptp | sed -n '/^frames:/,/^  trailer:/p'
$DAMAGE tapes/16k20f3s5-turning.iso.ptp -o long.ptp --seed 5 --leader +25 --drops 0.02 --doubles 0.05 --log - | grep -c '"drop"'
$TAPE info long.ptp | sed -n '/^frames:/p'
$DAMAGE tapes/16k20f3s5-turning.iso.ptp -o cut.ptp --seed 5 --leader -1000 --log -
$TAPE info cut.ptp | sed -n '/^frames:/,/^  trailer:/p'
