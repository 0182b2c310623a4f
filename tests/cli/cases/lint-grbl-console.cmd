# GRBL console lines ($I, $$, ?) in a file streamed to GRBL: one warning each (LinuxCNC stops on them),
# not an error and not two findings.
printf '$I  ; View build info\n$$  ; settings\n?\nG21 G90\nG0 X1 Y1\nG1 X2 F100\nM2\n' > plot.gcode
$TAPE -v lint plot.gcode; echo "exit $?"
