(helical entry and circular pocket: swarf simulate helical_pocket.nc --stock box:0,0,0,60,40,20 --tool flat:6 --flutes 3)
G21 G90 G17
S6000 M3
G0 X33 Y20 Z22
G0 Z20.5
G1 Z20 F300
G3 X33 Y20 Z19 I-3 J0 F600
G3 X33 Y20 Z18 I-3 J0
G3 X33 Y20 Z17 I-3 J0
G3 X33 Y20 Z17 I-3 J0
G1 X36 F600
G3 X36 Y20 Z17 I-6 J0
G0 Z25
M30
