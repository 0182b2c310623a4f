$TAPE encode --code eia tapes/bad/eia-colon.txt -o out.ptp; status=$?; ls; exit $status
