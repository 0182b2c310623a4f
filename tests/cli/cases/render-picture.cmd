# A tape drawn as a picture at a true size: a PNG 300 pixels an inch (2.54 mm a frame is 30 px); --dpi
# and --effects need a picture's name; a bad effect is a usage error.
$TAPE encode --leader 10 --trailer 10 tapes/circle-examples.txt -o t.ptp
$TAPE render t.ptp -o t.png && head -c 8 t.png | od -An -c
$TAPE render t.ptp -o t.svg --dpi 300; echo "exit $?"
$TAPE render t.ptp -o t.png --effects blur=x --force; echo "exit $?"
$TAPE render t.ptp -o t.png --effects fog=1 --force; echo "exit $?"
