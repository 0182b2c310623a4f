# The leader keeps its length: one too short for the label is a usage error saying how long it must be.
$TAPE encode --leader 30 --label "DETAIL 17" tapes/gost-20999-format-example.txt -o out.ptp; echo "exit $?"; ls
$TAPE encode --code ita2 --label "A" tapes/telegram.ita2.txt -o out.hex8; echo "exit $?"
