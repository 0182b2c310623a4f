# A profile is read strictly: an unknown key, a bad format, a code given twice, a bare non-ASCII letter
# are usage errors naming the file, the line and the key.
export XDG_CONFIG_HOME=$PWD/config
base='name = "m"
kind = "lathe"
source = "test"
'
printf '%scolour = "red"\n' "$base" > unknown-key.toml
$TAPE lint --machine unknown-key.toml tapes/16k20f3s5-turning.txt; echo "exit $?"
printf '%s[format]\nspec = "N3 X+6"\n' "$base" > bad-format.toml
$TAPE lint --machine bad-format.toml tapes/16k20f3s5-turning.txt; echo "exit $?"
printf '%s[[code]]\ncode = "G10"\nmeaning = "a"\n[[code]]\ncode = "G10"\nmeaning = "b"\n' "$base" > twice.toml
$TAPE blocks --explain --machine twice.toml tapes/16k20f3s5-turning.txt; echo "exit $?"
printf '%sСтанок = 1\n' "$base" > cyrillic.toml
$TAPE machines show ./cyrillic.toml; echo "exit $?"
$TAPE lint --machine 16k20f3s5 --spec "N3 G2 X+53" tapes/16k20f3s5-turning.txt; echo "exit $?"
