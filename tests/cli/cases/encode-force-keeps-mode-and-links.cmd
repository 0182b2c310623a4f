# --force keeps the replaced file's mode, follows a symbolic link, and leaves other hard links alone.
$TAPE decode tapes/16k20f3s5-turning.iso.ptp -o out.txt
chmod 600 out.txt
$TAPE decode --force tapes/gost-20999-format-example.iso.ptp -o out.txt
stat -c '%a' out.txt
ln out.txt other-name.txt
ln -s out.txt link.txt
$TAPE decode --force tapes/16k20f3s5-turning.iso.ptp -o link.txt
test -L link.txt && echo "link.txt is still a symbolic link"
cmp -s out.txt tapes/16k20f3s5-turning.txt && echo "out.txt (the link's target) replaced"
cmp -s other-name.txt out.txt || echo "the other hard link keeps the old contents"
stat -c '%a' out.txt
