// As in POV-Ray, a linear_spline prism needs at least three points.
prism { linear_spline 0, 1, 2, <0, 0>, <1, 0> }
