# A range past the end of the tape, and one backwards: usage errors.
$TAPE render --from 10 --to 5000 tapes/gost-20999-format-example.iso.ptp -o x.svg; echo "exit $?"
$TAPE render --from 50 --to 10 tapes/gost-20999-format-example.iso.ptp -o x.svg; echo "exit $?"; ls
