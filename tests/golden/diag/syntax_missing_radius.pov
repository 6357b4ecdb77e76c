// The radius of the sphere is missing.
sphere { <0, 1, 0> }
