# A Fanuc mill program as received over RS-232: %, O number, Custom Macro B loops, M30, %.
# Nothing is reported that is not a real mistake; -v says which dialect and why.
$TAPE -v lint tapes/../tests/corpus/fanuc-mill-bolt-circle-while.nc
