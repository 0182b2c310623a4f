$TAPE decode tapes/16k20f3s5-turning.iso.ptp -o out.txt && $TAPE decode --force tapes/gost-20999-format-example.iso.ptp -o out.txt && head -2 out.txt
