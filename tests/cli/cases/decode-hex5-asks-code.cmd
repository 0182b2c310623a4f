# A 5-track image fits ITA2 and МТК-2 alike: without --code the reader is asked which.
$TAPE decode tapes/telegram.mtk2.hex5
echo "exit $?"
# info, which does not read 5-track codes, says what the image is instead of guessing ISO or EIA.
$TAPE info tapes/telegram.mtk2.hex5 | sed -n '2,3p'
