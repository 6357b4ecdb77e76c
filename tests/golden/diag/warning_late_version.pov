// #version after other statements is late; the version the scene ends with
// decides (here 3.6: gamma correction off without assumed_gamma).
#declare R = 1;
sphere { 0, R pigment { rgb <1, 0.5, 0.2> } }
#version 3.6;
