$TAPE read "serial:/dev/ttyS0?baud=9601" -o out.ptp; status=$?; ls; exit $status
