// Thin fins thinner than the slice pitch (0.03, 0.07 mm) and a 0.2 mm one, along y and along
// x, and a thin pin: features that fall between slices or between CL points.
cube([30, 30, 2]);
translate([5, 2, 2]) cube([0.03, 26, 6]);
translate([10.02, 2, 2]) cube([0.07, 26, 6]);
translate([15, 2, 2]) cube([0.2, 26, 6]);
translate([20, 7.01, 2]) cube([8, 0.03, 6]);
translate([20, 15.03, 2]) cube([8, 0.07, 6]);
translate([24.02, 24.02, 2]) cylinder(r = 0.1, h = 8, $fn = 12);
