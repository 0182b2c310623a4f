# A CR LF tape decodes with its CRs, says so, and encode --crlf gives the same tape back.
printf '%%\nN1 G01\nM02\n%%\n' > p.txt
$TAPE encode --crlf p.txt -o crlf.ptp && $TAPE decode crlf.ptp -o back.txt && $TAPE encode --crlf back.txt -o again.ptp && cmp crlf.ptp again.ptp && echo "the same tape"
$TAPE encode back.txt -o lf.ptp && ! cmp -s crlf.ptp lf.ptp && echo "without --crlf the CRs are dropped"
