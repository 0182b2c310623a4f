$TAPE blocks --charset koi7 tapes/koi7-comment.iso.ptp
