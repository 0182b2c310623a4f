# A Fanuc program found by number is shown by its O block as written, where it stands: after the '%'
# and a header comment, not "%O58214" at the '%' (the shape of cade_O58214.nc).
printf '%%\n(HEADER)\nO58214 (BORED PART)\nG18 G40 G80 G99\nM30\n%%\n' > o.nc
$TAPE search --program 58214 o.nc
