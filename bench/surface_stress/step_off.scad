// Convex corners off the slice lattice, inside the scanned area: a block on a plate at
// non-round coordinates and a turned 7-sided frustum. The ball rests on a corner over a cap
// of CL points around it.
cube([30, 30, 3]);
translate([7.33, 8.21, 0]) cube([10.44, 11.48, 9.13]);
translate([20.17, 20.03, 0]) rotate([0, 0, 17]) cylinder(r1 = 4.3, r2 = 1.1, h = 6.77, $fn = 7);
