// A product that overflows.
#declare X = 1e308 * 10;
