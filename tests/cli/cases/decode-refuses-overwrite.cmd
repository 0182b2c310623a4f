echo keep > out.txt; $TAPE decode tapes/16k20f3s5-turning.iso.ptp -o out.txt; status=$?; cat out.txt; exit $status
