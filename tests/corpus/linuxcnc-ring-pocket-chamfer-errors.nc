; circular pocket d60 x 8 deep in concentric rings, then an optional 1 mm chamfer on the edge
; d10 end mill, d10 90 deg chamfer mill; g54 x0 y0 at the pocket centre, z0 top face
g21 g17 g90 g94 g40 g49
t4 m6 (end mill d10 3fl)
g43 h4
s9000 m3 m8
#<pocket_r> = 30
#<tool_r> = 5
#<step> = 4
#<doc> = 2
#<depth> = -8
#<z> = 0
g0 x0 y0
g0 z2
o200 while [#<z> GT #<depth>]
  #<z> = [#<z> - #<doc>]
  o210 if [#<z> LT #<depth>]
    #<z> = #<depth>
  o210 endif
  g1 z#<z> f200
  #<rr> = #<step>
  o220 while [#<rr> LT [#<pocket_r> - #<tool_r>]]
    g1 x#<rr> y0 f900
    g3 x#<rr> y0 i[0 - #<rr>] j0
    #<rr> = [#<rr> + #<step>]
  o220 endwhile
  g1 x[#<pocket_r> - #<tool_r>] y0
  g3 x[#<pocket_r> - #<tool_r>] y0 i[#<tool_r> - #<pocket_r>] j0
  g1 x0 y0
o200 endwhile
g0 z5
#<chamfer> = 1
o230 if [#<chamfer> GT 0]
  (msg, chamfer pass follows
  t7 m6 (chamfer mill d10 90 deg)
  g43 h7
  s8000 m3
  g0 x0 y0
  g0 z2
  g1 z-1.5 f300
  g1 x29.5 y0 f600
  g3 x29.5 y0 i-29.5 j0
  g1 x0 y0
  g0 z5
o231 else
  (msg, no chamfer on this part)
o230 endif
g0 z30 m9
m5
g53 g0 z0
m2
