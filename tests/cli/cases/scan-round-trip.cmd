# A tape drawn at 300 dpi as a flatbed shows it (skewed, bowed, stained, dusty, blurred, noisy, saved as
# JPEG) reads back frame for frame, its direction told by its leader label; --debug-svg draws what was found.
$TAPE encode --leader 40 --trailer 20 --label "N1" tapes/circle-examples.txt -o t.ptp
$TAPE render t.ptp -o t.jpg --effects skew=2,bow=1,stains=3,dust=20,blur=1,noise=5,jpeg=85,seed=4
$TAPE scan t.jpg -o r.ptp --report report.txt --debug-svg found.svg; echo "exit $?"
cmp t.ptp r.ptp && echo "same frames"
sed -n 1p report.txt
xmllint --noout found.svg && echo "debug picture is valid SVG"
grep -c 'class="feed"' found.svg
