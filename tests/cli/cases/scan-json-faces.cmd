# The report as JSON (schema tape-scan/1); the tape seen from its back and turned half a turn (drawn
# mirrored, its start at the right) reads the same, its program telling the direction.
$TAPE encode --leader 20 --trailer 20 tapes/circle-examples.txt -o t.ptp
$TAPE render t.ptp -o back.png --mirror
$TAPE scan back.png -o r.ptp --json > report.json; echo "exit $?"
cmp t.ptp r.ptp && echo "same frames"
python3 -c 'import json; j = json.load(open("report.json")); s = j["images"][0]["strip"]
print(j["schema"], j["frames"], j["complete"], j["direction"]["basis"], j["direction"]["weak"], s["mirrored"], s["reversed"], s["holes"], round(s["dpi"]))'
$TAPE scan back.png -o s.ptp --start right --report s.txt; echo "exit $?"
cmp -s t.ptp s.ptp || echo "--start right reads it the other way"
