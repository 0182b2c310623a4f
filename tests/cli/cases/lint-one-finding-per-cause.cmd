# One finding per cause: a comment that lost its '(', a missing END 2 inside DO 1, a missing o101
# endif inside o100 sub, and a tape cut in the middle of a block without end of program.
printf '%%\nO1\nT1 D=10. CR=0. - FLAT END MILL)\nM30\n%%\n' | $TAPE lint --dialect fanuc; echo "exit $?"
printf '%%\nO2\n#1=0\nWHILE [#1 LT 2] DO 1\n#2=0\nWHILE [#2 LT 2] DO 2\n#2=#2+1\nEND 1\nM30\n%%\n' | $TAPE lint --dialect fanuc; echo "exit $?"
printf 'o100 sub\no101 if [#1 GT 0]\ng0 x1\no100 endsub\nm2\n' | $TAPE lint --dialect linuxcnc; echo "exit $?"
