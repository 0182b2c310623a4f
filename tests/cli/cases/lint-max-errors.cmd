# --max-errors limits the findings of each lint rule; the rest are counted; the exit status stays.
{ printf '%%\n'; for i in $(seq 1 8); do printf 'N%03d G01 X1 X2\n' "$i"; done; printf 'N999 M02\n'; } > many.txt
$TAPE lint --max-errors 2 many.txt; echo "exit $?"
