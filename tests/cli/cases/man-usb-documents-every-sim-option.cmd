# Every option tape-adapter-sim --help lists is documented in man/tape-usb.7.
man_text=$(sed 's/\\-/-/g' tapes/../man/tape-usb.7)
sim=$(dirname "$TAPE")/tape-adapter-sim
missing=0
for opt in $("$sim" --help | grep -oE -- '--[a-z][a-z-]+' | sort -u); do
  grep -q -- "$opt" <<<"$man_text" || { echo "tape-adapter-sim: $opt is not in man/tape-usb.7"; missing=1; }
done
echo "checked"
exit $missing
