// A bezier_spline prism has four points per segment.
prism { bezier_spline 0, 1, 6, <0, 0>, <1, 0>, <1, 1>, <1, 1>, <0, 1>, <0, 0> }
