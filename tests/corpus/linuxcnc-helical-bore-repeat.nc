; helically interpolate a d40 bore through a 6 mm aluminium plate with a d6 end mill
; g54 at the bore centre, z0 on top; the slug falls onto the sacrificial board
g21 g17 g90 g40 g49 g94
g64 p0.01
t4 m6 (end mill d6 3fl)
g43 h4
s9000 m3
m8
#<r> = [20 - 3]          ; path radius = bore radius - tool radius
#<step> = 1.0            ; depth per turn
#<turns> = 7             ; from z0.5 down to z-6.5
g0 x0 y0
g0 z2
g1 z0.5 f300
g1 x#<r> y0 f600
o200 repeat [#<turns>]
  g91 g3 x0 y0 z[0 - #<step>] i[0 - #<r>] j0 f800   ; one full turn, incremental
o200 endrepeat
g90
g3 x#<r> y0 i[0 - #<r>] j0 f600     ; flat clean-up turn at full depth
g1 x[#<r> - 1] y0                   ; come off the wall
g0 z10
m9
m5
g53 g0 z0
m30
