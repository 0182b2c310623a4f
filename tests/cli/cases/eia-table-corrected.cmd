sed "s/^%    1,2,4 /%    1,3,4 /" tapes/../data/eia-rs244.tab > fixed.tab && printf "%%\nN1\n" | $TAPE --eia-table fixed.tab encode --code eia --leader 0 --trailer 0 | od -An -tx1
