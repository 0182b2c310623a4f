# Russian text punched in МТК-2: a shift only where the register changes, lower case as capitals,
# CR LF at each line end; read back the same (in capitals).
printf 'Москва 15 мая\nЦЕХ 4, ШПИНДЕЛЬ\n' >t.txt
$TAPE encode --code mtk2 --leader 2 --trailer 2 -f hex5 t.txt
$TAPE encode --code mtk2 tapes/telegram.mtk2.txt -o t.hex5
$TAPE decode --code mtk2 t.hex5 | cmp - tapes/telegram.mtk2.txt && echo "round trip: same text"
$TAPE show --code mtk2 t.hex5 | sed -n '101,112p'
