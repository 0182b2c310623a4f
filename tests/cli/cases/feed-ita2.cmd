# feed punches a text program in ITA2 when asked.
printf 'TEST 123\n' > t.txt
$TAPE feed --code ita2 --leader 0 --trailer 0 t.txt file:t.hex8 && grep -cv '^#' t.hex8 && $TAPE decode --code ita2 t.hex8
