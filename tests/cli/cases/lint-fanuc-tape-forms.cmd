# Fanuc as it comes off RS-232: DC2/DC4 around it, '%;', ',C'/',R' corner words, and what follows the
# end-of-record '%' (not read by the controller) is no program.
printf '\022%%;\r\nO1234(PART);\r\nG01 X10. Y10. ,C1. F100;\r\nG01 X20. ,R2.;\r\nM30;\r\n%%\r\nSOME TRAILING JUNK\r\n\024' > cap.nc
$TAPE -v lint --input image -p space cap.nc; echo "exit $?"
$TAPE blocks --input image -p space cap.nc
