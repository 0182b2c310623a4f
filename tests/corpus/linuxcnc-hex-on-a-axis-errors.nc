; hex 24 a/f x 20 long on the end of a d30 bar held in the 4th axis chuck (a turns about x)
; flats cut with the bottom of a d16 end mill; g54: x0 at the bar end face, y0 z0 on the bar axis
g21 g17 g90 g94 g40 g49 g80
t3 m6 (end mill d16 4fl)
g43 h3
s5000 m3
#<af> = 24
#<len> = 20
#<stock_r> = 15
#<doc> = 1
#<cutter_r> = 8
#<chord> = sqrt[[#<stock_r> * #<stock_r>] - [[#<af> / 2] * [#<af> / 2]]
(debug, half chord of the flat = #<chord>)
g0 a0
g0 x[#<cutter_r> + 2] y-5 z[#<stock_r> + 5]
m8
o300 repeat [6]
  #<z> = #<stock_r>
  o310 while [#<z> GT [#<af> / 2]]
    #<z> = [#<z> - #<doc>]
    o320 if [#<z> LT [#<af> / 2]]
      #<z> = [#<af> / 2]
    o320 endif
    g0 x[#<cutter_r> + 2] y-5
    g0 z#<z>
    g1 x[#<cutter_r> - #<len>] f600
    g1 y5
    g1 x[#<cutter_r> + 2]
    g0 z[#<stock_r> + 5]
  o310 endwhile
  g91 g0 a60 g90
o300 endrepeat
g0 z50 m9
m5
g53 g0 z0
m30
