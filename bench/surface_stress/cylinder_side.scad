// A coarse 12-sided cylinder lying on its side (axis along x, facet edges along x).
rotate([0, 90, 0]) cylinder(r = 8, h = 40, $fn = 12);
