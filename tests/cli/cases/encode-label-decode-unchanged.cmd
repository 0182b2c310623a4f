# A label in the leader: the program from its start on and the decoded text are the same as without it.
$TAPE encode --label "DETAIL 17" tapes/gost-20999-format-example.txt -o with.ptp
$TAPE encode tapes/gost-20999-format-example.txt -o without.ptp
cmp <(tail -c +101 with.ptp) <(tail -c +101 without.ptp) && echo "same from frame 101"
cmp <(head -c 100 with.ptp) <(head -c 100 without.ptp) >/dev/null || echo "leaders differ"
cmp <($TAPE decode with.ptp) <($TAPE decode without.ptp) && echo "same decoded text"
$TAPE -v decode with.ptp >/dev/null
$TAPE info with.ptp | grep -E 'leader label|leader:|data:'
$TAPE blocks with.ptp | head -3
$TAPE blocks --json with.ptp | grep -o '"leader_label": {[^}]*}'
