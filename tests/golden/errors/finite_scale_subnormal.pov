// A scale so small that its inverse overflows.
sphere { 0, 1 scale 1e-320 }
