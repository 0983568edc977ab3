// A Minkowski-rounded box: 30 x 20 x 8 grown by a sphere of radius 2 (many small facets).
minkowski() {
  cube([30, 20, 8]);
  sphere(r = 2, $fn = 24);
}
