# machine = "NAME" in a [[machine]] takes a machine profile's line settings (its own keys override
# them); a profile that is not there, or a key of the machine that is wrong after it, is said with the
# configuration's file, line and key.
export XDG_CONFIG_HOME=$PWD/config
mkdir programs received
base='[library]
programs = "programs"
received = "received"
[[machine]]
name = "lathe-1"
device = "serial:/dev/nonexistent?baud=9600"
'
printf '%smachine = "no-such-control"\n' "$base" > unknown-profile.toml
$TAPE dnc --config unknown-profile.toml; echo "exit $?"
printf '%smachine = "16k20f3s5"\nrate = -1\n' "$base" > bad-override.toml
$TAPE dnc --config bad-override.toml; echo "exit $?"
