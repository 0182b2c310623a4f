# feed sends the program exactly as written; --percent wraps it, never doubling a '%' already there.
printf 'N1 G00 X1\nN2 M30\n' > bare.txt
printf '%%\nN1 G00 X1\nN2 M30\n%%\n' > framed.txt
$TAPE feed --leader 0 --trailer 0 bare.txt file:a.ptp && $TAPE decode a.ptp && echo
echo ---
$TAPE feed --leader 0 --trailer 0 --percent bare.txt file:b.ptp && $TAPE decode b.ptp && echo
echo ---
$TAPE feed --leader 0 --trailer 0 --percent framed.txt file:c.ptp && $TAPE decode c.ptp
