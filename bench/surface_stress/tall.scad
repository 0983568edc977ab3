// Tall: a 100 mm stepped tower with a 60 deg cone on top.
cube([20, 20, 40]);
translate([3, 3, 40]) cube([14, 14, 40]);
translate([10, 10, 80]) cylinder(r1 = 6, r2 = 0.5, h = 20, $fn = 64);
