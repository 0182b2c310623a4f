# A bad tape dnc configuration is a usage error naming the file, the line and the key, said before any
# line is opened: a syntax error, an unknown key, a value out of range, a name given twice, a missing
# folder, a bad device string, text outside quotes, a folder or a FIFO given. tape dnc status reads
# only the control socket's place from it.
mkdir programs received
base='[library]
programs = "programs"
received = "received"
'
machine='[[machine]]
name = "mill-1"
device = "serial:/dev/nonexistent?baud=9600"
'
printf '%s%s' "$base" "$machine" > ok.toml
printf '%s%srat = 960\n' "$base" "$machine" > unknown-key.toml
$TAPE dnc --config unknown-key.toml; echo "exit $?"
printf '%s%srate = -5\n' "$base" "$machine" > bad-rate.toml
$TAPE dnc --config bad-rate.toml; echo "exit $?"
printf '%s%sparity = "sometimes"\n' "$base" "$machine" > bad-parity.toml
$TAPE dnc --config bad-parity.toml; echo "exit $?"
printf '%s%s%s' "$base" "$machine" "$machine" > twice.toml
$TAPE dnc --config twice.toml; echo "exit $?"
printf '[library]\nprograms = "nowhere"\nreceived = "received"\n%s' "$machine" > no-folder.toml
$TAPE dnc --config no-folder.toml; echo "exit $?"
printf '%s[[machine]]\nname = "mill-1"\ndevice = "serial:/dev/ttyS0?baud=9601"\n' "$base" > bad-baud.toml
$TAPE dnc --config bad-baud.toml; echo "exit $?"
printf '%s[[machine]]\nname = "../mill"\ndevice = "serial:/dev/ttyS0"\n' "$base" > bad-name.toml
$TAPE dnc --config bad-name.toml; echo "exit $?"
printf '%s[[machine]\nname = "x"\n' "$base" > syntax.toml
$TAPE dnc --config syntax.toml; echo "exit $?"
# A bare non-ASCII character is refused before toml++ 3.3.0 parses it (it reaches __builtin_unreachable).
printf '%s[[machine]]\nname = Фрезер\ndevice = "serial:/dev/ttyS0"\n' "$base" > bare-text.toml
$TAPE dnc --config bare-text.toml; echo "exit $?"
printf '%s' "$base" > no-machine.toml
$TAPE dnc --config no-machine.toml; echo "exit $?"
# --config names a file: a folder or a FIFO is refused by name (a FIFO before anything waits on it).
$TAPE dnc --config programs; echo "exit $?"
mkfifo fifo.toml
$TAPE dnc --config fifo.toml; echo "exit $?"
# tape dnc status reads only runtime_directory: a machine's bad key is the service's to say, not its.
printf '[service]\nruntime_directory = "nowhere"\n%s' "$machine" > status.toml
printf 'rat = 5\n' >> status.toml
$TAPE dnc status --config status.toml; echo "exit $?"
$TAPE dnc status --config syntax.toml; echo "exit $?"
$TAPE dnc status; echo "exit $?"
$TAPE dnc; echo "exit $?"
ls received
