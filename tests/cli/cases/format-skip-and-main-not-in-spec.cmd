# A format without '/' or ':' cannot carry a skipped block or a main block: format refuses them
# rather than write what lint --spec would reject.
printf '%%\n/N1 G1\n:2 G2\nN3 M02\n' | $TAPE format --spec "N03 G02 M02"
