# 12 has no room in X+05 (no digit before the point): an error naming the block, not 0.00012.
printf '%%\nN1 G1 X12\nN2 X.00012\nN3 M02\n' | $TAPE format --spec "DS N03 G02 X+05 M02" -o out.txt; status=$?; ls; exit $status
