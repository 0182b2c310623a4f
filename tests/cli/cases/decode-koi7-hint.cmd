# A КОИ-7 tape read without --charset koi7: the Latin letters between SO and SI are said to be Russian.
$TAPE decode tapes/koi7-comment.iso.ptp > /dev/null
$TAPE info tapes/koi7-comment.iso.ptp | grep advice
