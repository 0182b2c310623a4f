# A clean ASCII tape whose text reads about as well backwards (CR LF before each line, no leader) is
# text all the same: the scan says what it saw, not "no text".
printf '\x8d\x0a\xd7\xc5\xcc\xc3\xcf\x4d\xc5\xa0\xd4\xcf\xa0\x53\x50\xc5\xd2\xd2\x59\x53\x8d\x0a\xd7\xc5\xcc\xc3\xcf\x4d\xc5' > t.ptp
$TAPE render t.ptp -o t.png
$TAPE scan t.png -o s.ptp; echo "exit $?"
cmp t.ptp s.ptp && echo "read back"
