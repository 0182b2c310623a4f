# Planted mistakes in a Fanuc macro program, as JSON: rule, severity, position, message; a summary.
$TAPE lint --json --dialect fanuc tapes/../tests/corpus/fanuc-mill-grid-macro-errors.nc; echo "exit $?"
