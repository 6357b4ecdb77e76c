// A rotation angle that overflows.
sphere { 0, 1 rotate 1e308 * 10 * x }
