// A sum that overflows.
#declare X = 1.5e308 + 1.5e308;
