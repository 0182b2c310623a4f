# blocks --explain with the 16К20Ф3С5's profile names every code of the sample tapes: G27, G58, G26, G10,
# the feed modes of table 3 with the feed they run at, T and M with the acknowledgement digit; a word
# whose digit count is off the format is said to be not read.
export XDG_CONFIG_HOME=$PWD/config
$TAPE blocks --explain --machine 16k20f3s5 tapes/16k20f3s5-turning.iso.ptp; echo "exit $?"
$TAPE blocks --explain --machine n22-1m tapes/16k20f3s5-turning.eia.ptp; echo "exit $?"
$TAPE blocks --explain --lang ru --machine 16k20f3s5 tapes/16k20f3s5-turning.txt; echo "exit $?"
