# Three reads, one with 12 more blank frames of trailer: one problem line for the stretch, not twelve.
cp tapes/gost-20999-format-example.iso.ptp a.ptp
cp tapes/gost-20999-format-example.iso.ptp b.ptp
cat tapes/gost-20999-format-example.iso.ptp > c.ptp
head -c 12 /dev/zero >> c.ptp
$TAPE restore a.ptp b.ptp c.ptp -o r.ptp; echo "exit $?"
