// vlength() of a vector whose length overflows.
#declare X = vlength(<1e200, 1e200, 0>);
