// degrees() that overflows.
#declare X = degrees(1e308);
