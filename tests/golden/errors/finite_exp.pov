// exp() that overflows.
#declare X = exp(1000);
