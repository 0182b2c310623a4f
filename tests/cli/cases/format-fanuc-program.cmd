# A Fanuc program rewritten for a fixed format: its O number and the end-of-record '%' are kept as
# they were; macro statements and values cannot be written in such a format, and say so.
printf '%%\nO0100\nG01 X1.5 F100.\nN20 G00 X2\nM30\n%%\n' > plain.nc
$TAPE format --spec "N03 G02 X+053 F031 M02" plain.nc; echo "exit $?"
printf '%%\nO0100\n#1=2.5\nG01 X#1 F100.\nM30\n%%\n' > macro.nc
$TAPE format --spec "N03 G02 X+053 F031 M02" macro.nc; echo "exit $?"
