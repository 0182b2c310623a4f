# An empty --spec is a usage error, not "no spec" (it used to read an empty optional).
$TAPE format --spec "" tapes/gost-20999-format-example.txt
