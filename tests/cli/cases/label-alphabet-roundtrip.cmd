# The whole alphabet of the font, Latin and Cyrillic capitals and digits, punched in the leader of a
# program in ISO and in EIA, is read back by info and blocks as punched; the decoded program is unchanged.
ALPHA="ABCDEFGHIJKLMNOPQRSTUVWXYZ 0123456789 АБВГДЕЁЖЗИЙКЛМНОПРСТУФХЦЧШЩЪЫЬЭЮЯ -./"
for code in iso eia; do
  txt=tapes/gost-20999-format-example.txt
  [ $code = eia ] && txt=tapes/gost-20999-format-example.eia.txt
  $TAPE encode --code $code --leader 480 --label "$ALPHA" $txt -o $code.ptp
  $TAPE info $code.ptp | grep 'leader label'
  $TAPE blocks $code.ptp | head -1
  $TAPE decode $code.ptp | cmp - $txt && echo "$code: decoded text unchanged"
done
$TAPE label "$ALPHA" -o alone.ptp && $TAPE info --json alone.ptp | grep -o '"leader_label": {"text": "[^"]*"'
