# What tape scan refuses, and how: a strip too short to tell its feed holes (bad data, 1), a file that
# is no picture (bad data, 1: refused on its first bytes), a number of tracks tape does not have
# (usage, 2), an output that exists.
printf '%%\nN1\n' > short.txt
$TAPE encode --leader 2 --trailer 2 short.txt -o short.ptp
$TAPE render short.ptp -o short.png
$TAPE scan short.png -o r.ptp; echo "exit $?"
echo "not a picture" > text.png
$TAPE scan text.png -o r.ptp; echo "exit $?"
$TAPE scan short.png -o r.ptp --tracks 6; echo "exit $?"
touch exists.ptp
$TAPE scan short.png -o exists.ptp; echo "exit $?"
# No output over a picture read, and no two outputs in one file, nothing written either way.
$TAPE encode tapes/circle-examples.txt -o circle.ptp
$TAPE render circle.ptp -o circle.png
cp circle.png kept.png
$TAPE scan circle.png -o circle.png --force; echo "exit $?"
$TAPE scan circle.png -o r2.ptp --report r2.ptp; echo "exit $?"
$TAPE restore circle.png circle.ptp -o circle.png --force; echo "exit $?"
cmp circle.png kept.png && test ! -e r2.ptp && echo "nothing written"
$TAPE render circle.ptp -o circle.ptp --force; echo "exit $?"
