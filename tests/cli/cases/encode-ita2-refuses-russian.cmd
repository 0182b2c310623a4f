# ITA2 has no Russian: the character is named with its line and column, and МТК-2 suggested.
printf 'OK\nПРИВЕТ\n' | $TAPE encode --code ita2 -o t.hex5
echo "exit $?"
printf 'ЁЛКА\n' | $TAPE encode --code mtk2 -o t.hex5
echo "exit $?"
ls
