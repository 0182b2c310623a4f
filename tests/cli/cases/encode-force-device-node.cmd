# --force onto a character device, a FIFO or /dev/stdout writes into it; the node is never replaced.
# The nodes are private copies made here (a null device node as root, a link like /dev/stdout), so a
# regression cannot replace the system's /dev/null or /dev/stdout.
if mknod null c 1 3 2>/dev/null; then node=null; else node=/dev/null; fi
$TAPE encode tapes/16k20f3s5-turning.txt -o "$node" --force; echo "exit $?"
test -c "$node" && echo "the null device is still a character device"
mkfifo pipe
timeout 20 cat pipe > from-pipe.ptp &
$TAPE encode tapes/16k20f3s5-turning.txt -o pipe --force; echo "exit $?"
wait
test -p pipe && echo "pipe is still a FIFO"
cmp from-pipe.ptp tapes/16k20f3s5-turning.iso.ptp && echo "the FIFO carried the tape"
ln -s /proc/self/fd/1 stdout-link
$TAPE decode tapes/16k20f3s5-turning.iso.ptp -o stdout-link --force > via-stdout.txt; echo "exit $?"
test -L stdout-link && echo "the /dev/stdout-like link is still a link"
cmp via-stdout.txt tapes/16k20f3s5-turning.txt && echo "the link carried the program"
ls *.tmp* 2>/dev/null; echo "no temporary files left"
