$TAPE decode -k tapes/bad/parity-error.ptp -o out.txt; status=$?; grep -c $'\xEF\xBF\xBD' out.txt; exit $status
