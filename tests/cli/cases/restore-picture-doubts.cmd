# A picture's doubtful frames weigh less than a sure reading: restored from the picture itself, one frame
# fewer stays contested than from the same frames given as a plain read, which carries no doubts.
$TAPE encode --leader 20 --trailer 20 tapes/circle-examples.txt -o t.ptp
$TAPE render t.ptp -o p.png --dpi 80 --effects blur=1.5,noise=25,dust=40,skew=2,seed=1
$TAPE scan p.png -o s.ptp -f raw >/dev/null 2>&1; echo "scan: exit $?"
$TAPE restore p.png t.ptp -o from-picture.ptp --report picture.txt 2>/dev/null; echo "from the picture: exit $?"
sed -n 4p picture.txt | cut -d' ' -f1-11
$TAPE restore s.ptp t.ptp -o from-read.ptp --report read.txt 2>/dev/null; echo "from its frames alone: exit $?"
sed -n 4p read.txt | cut -d' ' -f1-11
cmp t.ptp from-picture.ptp && echo "restored as punched"
