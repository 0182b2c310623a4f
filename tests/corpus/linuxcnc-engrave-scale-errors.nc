; engrave a 100 mm scale on a steel rule blank with a 60 deg v-bit
; ticks 1 mm apart: 6 mm every 10, 4.5 mm every 5, 3 mm otherwise
; g54: x0 at the zero tick, y0 on the scale edge, z0 on top
g21 g17 g90 g40 g49 g94
t5 m6 (v-bit 60 deg 0.1 tip)
g43 h5
s18000 m3
#<depth> = -0.15
#<n> = 0
g0 z3
o300 while [#<n> LE 100]
  o310 if [[#<n> MOD 10] EQ 0]
    #<len> = 6.0
  o310 elseif [[#<n> MOD 5] EQ 0
    #<len> = 4.5
  o310 else
    #<len> = 3.0
  o310 endif
  g0 x#<n> y0
  g1 z#<depth> f120
  g1 y#<len> f600
  g0 z1
  #<n> = [#<n> + 1]
o300 endwhile
o320 endif
g0 z20
m5
g53 g0 z0
m2
