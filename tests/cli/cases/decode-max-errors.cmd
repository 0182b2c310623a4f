# After --max-errors messages of one kind the rest are counted in one line; the exit status stays 1.
printf '\xa5\x0a' > noise.ptp
for i in $(seq 1 40); do printf '\x01\x02\x03\x04\x05' >> noise.ptp; done
$TAPE decode -c iso --keep-going --max-errors 3 noise.ptp -o out.txt; echo "exit $?"
$TAPE decode -c iso --max-errors 3 noise.ptp -o out2.txt; echo "exit $?"
$TAPE decode -c iso --keep-going --max-errors 0 noise.ptp -o out3.txt 2>&1 | wc -l
$TAPE decode -c iso --max-errors -1 noise.ptp; echo "exit $?"
