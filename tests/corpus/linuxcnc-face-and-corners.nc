; face the top of a 150 x 100 block, then round the two front corners r15
; g54: x0 y0 at the back left corner (the block lies in -y), z0 on the faced top
g21 g17 g90 g40 g49 g94
t1 m6 (face mill d50)
g43 h1
s2200 m3 m8
g0 x-30 y10
g0 z5
g1 z0
g1 x180 f900
g1 y-30
g1 x-30
g1 y-70
g1 x180
g1 y-110
g1 x-30
g0 z25
m9
; tool centre path for r15 corners with a d12 end mill: offset 6, path radius 21
t2 m6 (end mill d12)
g43 h2
s6000 m3 m8
g0 x-6 y-70
g0 z2
g1 z-10 f300
g1 y-85 f700
g3 x15 y-106 i21 j0
g1 x135
g3 x156 y-85
g1 y-70
g0 z25
m9
m5
g53 g0 z0
