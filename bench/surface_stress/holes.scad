// Holes narrower than the tool (d 2, 0.8, 0.3 mm) and one wider (d 6), drilled 8 mm deep.
$fn = 48;
difference() {
  cube([30, 20, 10]);
  translate([5, 10, 2]) cylinder(d = 2, h = 10);
  translate([10, 10, 2]) cylinder(d = 0.8, h = 10);
  translate([14, 10, 2]) cylinder(d = 0.3, h = 10);
  translate([22, 10, 2]) cylinder(d = 6, h = 10);
}
