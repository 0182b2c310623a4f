# An ISO program written as hex8 and read back by extension and by content (code detected as usual).
$TAPE encode tapes/circle-examples.txt -o c.hex8 --leader 3 --trailer 3
sed -n '1,6p' c.hex8
$TAPE -v decode c.hex8 | cmp - tapes/circle-examples.txt && echo "same program"
cp c.hex8 c.dump
$TAPE info c.dump | sed -n '1,3p'
