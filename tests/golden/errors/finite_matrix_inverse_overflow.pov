// A matrix whose determinant underflows to 0 (its inverse would overflow).
sphere { 0, 1 matrix <1e-200, 0, 0, 0, 1e-200, 0, 0, 0, 1e-200, 0, 0, 0> }
