# Bad frames shaded red with their ids and reasons; the character beside them is '!'.
$TAPE render tapes/bad/parity-error.ptp | grep -E 'class="mark|>!<' | head -5
