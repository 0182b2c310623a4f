script -qec "$TAPE encode tapes/16k20f3s5-turning.txt" /dev/null | tr -d "\r"
