# One profile with the source of every value: the 16К20Ф3С5 with the Н22-1М from the 1991 course text, by
# an alias in Cyrillic; the Fanuc 18 with its line settings; a name there is no profile for.
export XDG_CONFIG_HOME=$PWD/config
$TAPE machines show 16К20Ф3С5; echo "exit $?"
$TAPE machines show fanuc-18; echo "exit $?"
$TAPE machines show no-such-control; echo "exit $?"
