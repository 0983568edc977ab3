%
(seed 001 section 4.2 validation cut: ball end mill D8, helix 30, 3600 rpm, 200 mm/min)
(stock box:0,0,0,50,30,20 ; steady 2 mm deep cut to x30, then a ramp out: transient)
G21 G90 G17
S3600 M3
G0 X-5 Y15 Z25
G0 Z18
G1 X30 F200
G1 X55 Z20
G0 Z25
M30
%
