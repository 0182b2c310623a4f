; probe the top face and the left edge of the stock, set g54 z0 and x0
; linuxcnc 2.8 or later, touch probe in the spindle as tool 99, tip d2.0
(MSG,Jog the probe about 10 mm above the stock near its front left corner, then cycle start)
m0
g21 g17 g90 g40 g49 g94
t99 m6
g43 h99
#<clear> = 5.0
#<tip_radius> = 1.0
; --- top face: probe down from where the operator left the probe
g91
g38.2 z-20 f100
o100 if [#5070 EQ 0]
  (abort,probe did not touch the top face)
o100 endif
g90
g10 l20 p1 z0           ; contact point becomes z0 of g54
; --- left edge: back off, step left and down, probe +x
g91
g0 z[#<clear>]
g0 x-15
g0 z-10
g38.2 x20 f100
o110 if [#5070 EQ 0]
  (abort,probe did not touch the left edge)
o110 endif
g90
g10 l20 p1 x[0 - #<tip_radius>]   ; centre of the tip is one radius left of the edge
g91
g0 x-3
g0 z15
g90
(DEBUG,G54 set: x offset #5221 z offset #5223)
m2
