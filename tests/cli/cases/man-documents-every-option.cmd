# Every option that --help lists for a subcommand, and every lint rule, is documented in man/tape.1 (plot's in man/tape-plot.1).
man_text=$(sed 's/\\-/-/g' tapes/../man/tape.1 tapes/../man/tape-plot.1)
missing=0
for sub in "" encode decode show info blocks lint format search feed receive emulate read punch devices restore diff \
  adapter "adapter info" "adapter config" "adapter selftest" label render plot; do
  for opt in $($TAPE $sub --help | grep -oE -- '--[a-z][a-z-]+' | sort -u); do
    grep -q -- "$opt" <<<"$man_text" || { echo "tape $sub: $opt is not in man/tape.1"; missing=1; }
  done
done
# ...and every lint rule.
for rule in $($TAPE lint --rules | cut -d' ' -f1); do
  grep -q -- "$rule" <<<"$man_text" || { echo "lint rule $rule is not in man/tape.1"; missing=1; }
done
echo "checked"
exit $missing
