// A poly's order and its number of coefficients.
#version 3.7;
global_settings { assumed_gamma 1.0 }
poly { 1, <1, 1, 1, 1> }
poly { 36, <1, 1, 1, 1> }
quartic { <1, 0, 0, 0, 1, 0, 0, 1, 0, -1> }
poly { 2, <1, 0, 0, 0, 1, 0, 0, 1, 0> }
cubic { <0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1> }
sphere { 0, 1 sturm }
