; linuxcnc lathe: pin d22 x 30 with an m12x1.75 end, stock d25
; x in diameter mode (g7), z0 on the faced end, feed per revolution
g18 g7 g21 g90 g95 g40
t1 m6 g43 (turning tool 35 deg vbmt)
g96 d2500 s180 m3
m8
g0 x27 z2
g1 z0 f0.15
g1 x-0.4
g0 z1
g0 x22.5
g1 z-30 f0.2
g1 x25.5
g0 z1
g0 x19
g1 z-18
g0 x22 z1
g0 x15.5
g1 z-18
g0 x20 z1
g0 g1 x10 z1 f0.1
g1 z0
g1 x12 z-1 x11.96
g1 z-18
g1 x22
g1 z-30
g1 x26
g0 x30 z20 m9
; thread m12x1.75, 60 deg
t2 m6 g43 (threading insert 60 deg ext)
g97 s600 m3
g0 x14 z4
g76 p1.75 z-16 i-1 j0.2 k1.07 r1.5 q29.5 h2 e0 l0
g0 x30 z20
m5
m2
