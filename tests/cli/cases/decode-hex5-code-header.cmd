# The code a hex5 header names is read back: no --code needed for a tape this tool wrote.
$TAPE encode --code mtk2 -f hex5 tapes/telegram.mtk2.txt -o t.hex5 && sed -n '2p' t.hex5
$TAPE decode t.hex5 | cmp - tapes/telegram.mtk2.txt && echo "read as МТК-2"
$TAPE info t.hex5 | sed -n '3p'
