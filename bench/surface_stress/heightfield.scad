// A heightfield (OpenSCAD surface()) from a 24 x 24 table of heights: a relief with peaks,
// a pit and a cliff; the cells are 1 mm.
scale([1, 1, 1]) surface(file = "heightfield.dat", center = false);
