// cosh() that overflows.
#declare X = cosh(1000);
