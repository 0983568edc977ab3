// Analytic: cone of base radius 10, height 10 (45 deg flank), apex at (0, 0, 10).
cylinder(r1 = 10, r2 = 0, h = 10, $fn = 256);
