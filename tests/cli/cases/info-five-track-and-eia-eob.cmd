# info takes --code ita2|mtk2; an EIA tape starting with many end-of-block frames is EIA, not binary.
$TAPE info --code ita2 tapes/telegram.ita2.hex8 | sed -n '3p;/parity errors/p;/not in code/p'
{ for i in $(seq 1 25); do printf '\200'; done; cat tapes/16k20f3s5-turning.eia.ptp; } > eob.ptp && $TAPE info eob.ptp | sed -n '3p'
