# Pictures of a tape are reads for tape restore, beside tape images: each is read as tape scan reads it.
$TAPE encode --leader 20 --trailer 20 tapes/circle-examples.txt -o t.ptp
$TAPE render t.ptp -o front.jpg --effects skew=1,noise=5,jpeg=80,seed=1
$TAPE render t.ptp -o back.png --mirror --effects skew=-2,dust=30,seed=2
$TAPE restore front.jpg back.png t.ptp -o r.ptp --report report.txt; echo "exit $?"
cmp t.ptp r.ptp && echo "restored as punched"
sed -n 2,4p report.txt
