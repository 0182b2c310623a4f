$TAPE feed --leader 2 --trailer 2 tapes/16k20f3s5-turning.txt file:fed.ptp && $TAPE show fed.ptp | sed -n 1,6p
