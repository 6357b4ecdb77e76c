// A light moved out of range.
light_source { 1e308*x, 1 translate 1e308*x }
