// A matrix entry that overflows.
sphere { 0, 1 matrix <1, 0, 0, 0, 1, 0, 0, 0, 1, 1e308*10, 0, 0> }
