// Analytic: sphere of radius 10 about (0, 0, 0). Ball offset: tip = sqrt((10 + r)^2 - d^2) - r.
sphere(r = 10, $fn = 256);
