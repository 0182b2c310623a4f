# Fanuc: O number, ';' ends of block, a macro statement, the closing '%' as the end of record.
printf '%%\nO1234 (PLATE);\n#100=2;\nG00 X#100 Y0;\nIF [#100 EQ 2] GOTO 10;\nN10 M30;\n%%\n' | $TAPE blocks --json
