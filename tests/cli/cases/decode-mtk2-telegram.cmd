# A hand-made МТК-2 telegram (hex5): Russian, Latin-free, figures, CR CR LF line ends.
$TAPE decode --code mtk2 tapes/telegram.mtk2.hex5
