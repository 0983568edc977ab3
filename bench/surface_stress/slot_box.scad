// Steep and vertical walls: a 40 x 30 x 20 block with a deep 3 mm slot (walls at x = 10 and
// 13, exactly on slice planes and on the CL lattice), a 1.5 mm slot narrower than most
// balls, and a step whose face lies exactly at a slice height (z = 12.5).
difference() {
  cube([40, 30, 20]);
  translate([10, -1, 5]) cube([3, 32, 16]);
  translate([25, -1, 8]) cube([1.5, 32, 13]);
  translate([30, -1, 12.5]) cube([11, 32, 10]);
}
