# --max lists N findings in all, sorted by position; the rest are counted; the exit status stays.
{ printf '%%\n'; for i in $(seq 1 6); do printf 'N%03d G01 G00 X1 X2 F100\n' "$i"; done; printf 'N999 M02\n'; } > many.txt
$TAPE lint --dialect gost --max 3 many.txt; echo "exit $?"
