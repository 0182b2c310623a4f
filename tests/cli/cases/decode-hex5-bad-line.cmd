# A hex5 line with tracks 6-8 punched is no 5-track frame: rejected with its line number.
$TAPE decode --code ita2 tapes/bad/tracks-6-8.hex5
