# A byte-order mark at the start of a text program is skipped with a note, by encode and by every
# command reading text programs; the tape is the same as without it.
printf '\xef\xbb\xbf' > bom.txt && cat tapes/gost-20999-format-example.txt >> bom.txt
$TAPE encode bom.txt -o bom.ptp; echo "exit $?"
cmp bom.ptp tapes/gost-20999-format-example.iso.ptp && echo "same tape as without the mark"
$TAPE blocks bom.txt > /dev/null; echo "exit $?"
