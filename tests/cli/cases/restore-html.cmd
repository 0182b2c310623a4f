# The report as one HTML page: the places to check first (none here), the restored ones folded with the tape
# drawn around them, their frames marked and linked to the table, nothing fetched (no src or href outside the
# page), no script; an existing page is kept without --force.
D="$(dirname "$TAPE")/tape-damage"
for s in 11 12 13; do "$D" tapes/gost-20999-format-example.iso.ptp -o r$s.ptp --seed $s --damage 0.02; done
$TAPE restore r11.ptp r12.ptp r13.ptp -o out.ptp --report report.txt --html report.html; echo "exit $?"
grep -c '<script' report.html
grep -oE '(src|href)="[^#"][^"]*"' report.html | head -3
grep -o 'class="mark [a-z]*"' report.html | sort | uniq -c
grep -o '<tr class="[a-z]*" id="p[0-9]*"><td><a href="#f[0-9]*">' report.html | head -3
grep -o '<h2 id="[a-z]*">[^<]*</h2>' report.html
grep -o '<details[a-z ]*>' report.html
grep -c 'voted' report.txt
$TAPE restore r11.ptp r12.ptp r13.ptp -o out2.ptp --report report2.txt --html report.html; echo "exit $?"
