$TAPE encode --format holes --leader 1 --trailer 0 tapes/16k20f3s5-turning.txt | sed "7s/|  oo .   |/|  oo .  o|/" > damaged.holes && $TAPE decode damaged.holes
