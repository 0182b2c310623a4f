%
( flange - 6 holes d9 on pcd 80 - spot then peck drill )
( linuxcnc, mm, g54 at the flange centre, z0 on the top face )
o<bolt_circle> sub
  ; #1 holes  #2 pcd radius  #3 first angle  #4 depth  #5 retract plane  #6 peck  #7 feed
  #<i> = 0
  o<bc_loop> while [#<i> LT #1]
    #<a> = [#3 + #<i> * 360 / #1]
    g99 g83 x[#2 * cos[#<a>]] y[#2 * sin[#<a>]] z#4 r#5 q#6 f#7
    #<i> = [#<i> + 1]
  o<bc_loop> endwhile
  g80
o<bolt_circle> endsub

g21 g17 g90 g91.1 g40 g49 g94
g64 p0.02
t2 m6 (spot drill d10 90 deg)
g43 h2
g54 g0 x0 y0
s1600 m3
g0 z25 m8
o<bolt_circle> call [6] [40] [0] [-2.5] [2] [5] [150]
g0 z25
t3 m6 (drill d9 hss)
g43 h3
s900 m3
g0 z25
o<bolt_circle> call [6] [40] [0] [-16] [2] [3] [120]
g0 z50 m9
m5
g53 g0 z0
m2
%
