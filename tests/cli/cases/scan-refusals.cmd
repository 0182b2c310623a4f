# What tape scan refuses, and how: a strip too short to tell its feed holes (bad data, 1), a file that
# is no picture (I/O, 3), a number of tracks tape does not have (usage, 2), an output that exists.
printf '%%\nN1\n' > short.txt
$TAPE encode --leader 2 --trailer 2 short.txt -o short.ptp
$TAPE render short.ptp -o short.png
$TAPE scan short.png -o r.ptp; echo "exit $?"
echo "not a picture" > text.png
$TAPE scan text.png -o r.ptp; echo "exit $?"
$TAPE scan short.png -o r.ptp --tracks 6; echo "exit $?"
touch exists.ptp
$TAPE scan short.png -o exists.ptp; echo "exit $?"
