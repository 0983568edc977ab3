// Overhang / undercut: a cap of radius 12 on a stem of radius 4 on a plate. A drop-cutter sees
// only the cap's top; nothing under the cap may raise or lower the CL.
$fn = 96;
cube([40, 40, 3]);
translate([20, 20, 3]) cylinder(r = 4, h = 10);
translate([20, 20, 13]) cylinder(r = 12, h = 3);
