// POV-Ray closes a linear_spline prism left open, with a warning.
#version 3.7;
global_settings { assumed_gamma 1 }
prism { linear_spline 0, 1, 3, <0, 0>, <1, 0>, <1, 1> }
