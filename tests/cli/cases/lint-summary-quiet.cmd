# A clean program ends with one line of counts on stderr, as other linters do; -q silences it.
$TAPE lint tapes/gost-20999-format-example.txt; echo "exit $?"
$TAPE -q lint tapes/gost-20999-format-example.txt; echo "exit $?"
