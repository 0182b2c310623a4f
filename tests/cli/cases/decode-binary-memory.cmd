# A PDP-8 BIN loader tape: info names it, decode --to octal lists the words it loads, --to bin writes them
# as two bytes a word; a lost hole fails the checksum: named, nothing written without -k.
$TAPE decode --to octal tapes/bad/pdp8-bin-loader.bin
$TAPE decode --to bin tapes/bad/pdp8-bin-loader.bin -o m.bin && wc -c < m.bin
cp tapes/bad/pdp8-bin-loader.bin worn.bin && printf '\000' | dd of=worn.bin bs=1 seek=70 conv=notrunc 2>/dev/null
$TAPE decode --to octal worn.bin; echo "exit $?"
$TAPE decode --to octal -k worn.bin -o worn.txt; echo "exit $?"; wc -l < worn.txt
$TAPE decode --to bin tapes/16k20f3s5-turning.iso.ptp; echo "exit $?"
