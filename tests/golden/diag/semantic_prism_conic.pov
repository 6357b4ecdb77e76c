// conic_sweep prisms are refused by name.
prism { conic_sweep linear_spline 0.5, 1, 4, <0, 0>, <1, 0>, <0, 1>, <0, 0> }
