// A quadratic_spline prism whose last sub-prism does not return to its second point:
// POV-Ray stops ("Too few points in prism").
prism { quadratic_spline 0, 1, 6, <0, 0>, <1, 0>, <2, 1>, <1, 2>, <0, 1>, <0.5, 0> }
