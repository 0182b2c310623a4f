# The Elliott 920 telecode: punched with its own characters, found by auto, read back the same.
printf '(CONVERSION FOR MANDY, 15/2/71)\n£MAN\t8\t;+3 º ↑ ⑩\n' > s.txt
$TAPE encode --code elliott920 s.txt -o s.ptp && $TAPE decode s.ptp | cmp - s.txt && echo "the same text"
$TAPE info s.ptp | sed -n '3,4p'
$TAPE decode --code iso s.ptp > /dev/null; echo "as ISO: exit $?"
