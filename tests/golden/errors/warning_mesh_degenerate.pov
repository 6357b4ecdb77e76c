// A mesh's degenerate triangle is left out, with a warning, as POV-Ray does.
#version 3.7;
global_settings { assumed_gamma 1 }
mesh {
  triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
  triangle { <0, 0, 0>, <1, 1, 1>, <2, 2, 2> }
}
