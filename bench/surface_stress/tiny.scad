// Much smaller than the tool: a 1 x 0.6 x 0.4 mm block (run with a 20 mm ball).
translate([0.013, 0.007, 0]) cube([1, 0.6, 0.4]);
