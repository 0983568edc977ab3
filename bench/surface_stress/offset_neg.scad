// Far from the origin, entirely below z = 0, at non-lattice coordinates: a tilted block.
translate([-137.31, 212.93, -55.47]) rotate([7, 11, 23]) cube([25, 15, 10]);
