# Frames with tracks 6-8 read through hex8, and ITA2's national figure positions: findings with frame
# numbers, never guessed; with -k each is marked in the text (2>&1: messages beside the text).
printf '1F\n03\nC1\n03\n1B\n0D\n17\n' >t.hex8
$TAPE decode --code ita2 t.hex8 2>&1; echo " exit $?"
$TAPE decode --code ita2 -k t.hex8 2>&1; echo " exit $?"
$TAPE decode --code mtk2 -k t.hex8 2>&1; echo " exit $?"
