%
(thread mill m20x2.5 internal right hand, 4 holes pre-drilled d17.5 x 24 deep)
(linuxcnc, mm, g54 x0 y0 at the plate centre, z0 on the top face)
o<tm_hole> sub
  ; #1 x  #2 y  #3 major dia  #4 pitch  #5 thread depth (negative)  #6 tool dia  #7 feed
  #<r> = [[#3 - #6] / 2]
  #<turns> = [fup[abs[#5] / #4] + 1]
  #<zs> = [#5 - #4]
  g0 x#1 y#2
  g0 z1
  g1 z#<zs> f[#7 * 3]
  g1 x[#1 + #<r>] y#2 f[#7 / 2]
  #<k> = 0
  o110 do
    #<k> = [#<k> + 1]
    g3 x[#1 + #<r>] y#2 z[#<zs> + #<k> * #4] i[0 - #<r>] j0 f#7
  o110 while [#<k> LT #<turns>]
  g1 x#1 y#2
  g0 z5
o<tm_hole> endsub
g21 g17 g90 g40 g49 g80 g94 g91.1
g64 p0.01
t12 m6 (thread mill d12, single form 60 deg)
g43 h12
s6000 m3
g54 g0 x0 y0
g0 z25 m8
#<pitch> = 2.5
#<depth> = -20
o120 if [#<depth> LT -24]
  (abort, thread deeper than the drilled hole)
o120 else
  (msg, thread milling 4 holes m20x2.5)
o120 endif
o<tm_hole> call [-30] [-20] [20] [#<pitch>] [#<depth>] [12] [400]
o<tm_hole> call [30] [-20] [20] [#<pitch>] [#<depth>] [12] [400]
o<tm_hole> call [30] [20] [20] [#<pitch>] [#<depth>] [12] [400]
o<tm_hole> call [-30] [20] [20] [#<pitch>] [#<depth>] [12] [400]
g0 z50 m9
m5
g53 g0 z0
m30
%
