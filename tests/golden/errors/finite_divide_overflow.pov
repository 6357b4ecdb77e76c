// A quotient that overflows.
#declare X = 1 / 1e-320;
