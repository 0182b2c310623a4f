# --format holes and a .holes name are never replaced by raw because of the content: a bordered
# picture from another tool is reported where it does not follow the format.
printf '+----------+\n|  o o.ooo |\n+----------+\n' > framed.holes
$TAPE decode framed.holes; echo "exit $?"
$TAPE decode --format holes - < framed.holes; echo "exit $?"
cp framed.holes framed.pic
$TAPE decode --format holes framed.pic; echo "exit $?"
