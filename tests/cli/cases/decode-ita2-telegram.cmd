# An ITA2 telegram as an 8-track reader dumps it (hex8), read with --code ita2; the same as its text.
$TAPE decode --code ita2 tapes/telegram.ita2.hex8
$TAPE decode --code ita2 tapes/telegram.ita2.hex8 | cmp - tapes/telegram.ita2.txt && echo "same as tapes/telegram.ita2.txt"
