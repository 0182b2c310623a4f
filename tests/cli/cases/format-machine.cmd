# format --machine writes each block in the format its codes set: the course text's +276 pulses as
# X+000276 after G10, X+0276 after G11, X+00276 after G01. A word in millimetres for an axis counted in
# pulses is refused, not converted.
export XDG_CONFIG_HOME=$PWD/config
printf '%%\nN1 G10 X+276\nN2 G11 X+276\nN3 G01 X+276 F10600 S24 T1 M4\nN4 M102\n' > pulses.txt
$TAPE format --machine 16k20f3s5 pulses.txt; echo "exit $?"
printf '%%\nN1 G01 X-20. F10600\nN2 M102\n' > millimetres.txt
$TAPE format --machine 16k20f3s5 millimetres.txt; echo "exit $?"
$TAPE format pulses.txt; echo "exit $?"
