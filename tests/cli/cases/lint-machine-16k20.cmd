# lint with the 16К20Ф3С5's profile: the sample tapes (clean without it) break the Н22-1М's format where
# the course text's OCR is off (F2000, S 64, the seven-digit X words); a digit count off G10's "long"
# mode and a feed code whose first digit is not in table 3 are found in a program written for it.
export XDG_CONFIG_HOME=$PWD/config
$TAPE lint --machine 16k20f3s5 tapes/16k20f3s5-turning.iso.ptp; echo "exit $?"
$TAPE lint --machine 16k20f3s5 tapes/16k20f3s5-turning.eia.ptp; echo "exit $?"
printf '%%\nN001 G27 T101 M104\nN002 G10 X+12345 F10600\nN003 Z+000500 F30600\nN004 G11 X+0276 Z-0100\nN005 M202\nN006 M102\n' > long-mode.txt
$TAPE lint --machine 16k20f3s5 long-mode.txt; echo "exit $?"
