// Many small features: a 24-tooth gear outline and raised text on a plate.
module gear(n = 24, r = 12, t = 1.2) {
  polygon([for (i = [0:4 * n - 1])
    let(a = 360 * i / (4 * n), rr = (i % 4 < 2) ? r + t : r - t) [rr * cos(a), rr * sin(a)]]);
}
cube([60, 30, 2]);
translate([15, 15, 2]) linear_extrude(height = 4) difference() { gear(); circle(r = 3, $fn = 32); }
translate([31, 9, 2]) linear_extrude(height = 1.5) text("Swarf", size = 8, font = "Liberation Sans");
