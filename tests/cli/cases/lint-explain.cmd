$TAPE lint --explain word-order
$TAPE lint --explain no-such-rule; echo "exit $?"
