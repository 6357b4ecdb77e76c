// Cross-check with POV-Ray 3.7 (tests/unit/render_golden_test.cpp): CSG.
// A box with a sphere cut out (the cut face in the sphere's texture), a box
// with two holes (a difference of a union), a lens (the intersection of two
// spheres), a merge, a plane cut to a slab by an intersection, an `inverse`,
// a disc's half-space and an open cylinder inside a difference. References:
// povray -A, rendered by scripts/update-goldens.sh.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.55, 0.7, 0.9> }
camera { location <0, 5, -10> look_at <0, 0.8, 1> right x*16/9 angle 50 }
light_source { <-6, 12, -10>, color rgb 1 }
plane { y, 0 pigment { checker color rgb 0.85, color rgb 0.3 } finish { diffuse 0.8 } }
difference {
  box { <-1, 0, -1>, <1, 1.6, 1> pigment { color rgb <0.2, 0.45, 0.85> } }
  sphere { <0.6, 1.4, -0.6>, 0.9 pigment { color rgb <0.95, 0.8, 0.2> } }
  rotate <0, 20, 0> translate <-3.2, 0, 0>
}
difference {
  box { <-1, 0, -0.4>, <1, 1.4, 0.4> }
  union {
    cylinder { <-0.45, 0.7, -1>, <-0.45, 0.7, 1>, 0.3 }
    cylinder { <0.45, 0.7, -1>, <0.45, 0.7, 1>, 0.3 pigment { color rgb <0.9, 0.2, 0.2> } }
  }
  pigment { color rgb <0.3, 0.75, 0.35> }
  finish { phong 0.5 }
  rotate <0, -25, 0> translate <0, 0, 1.5>
}
intersection {
  sphere { <0, 0, -0.8>, 1.2 }
  sphere { <0, 0, 0.8>, 1.2 }
  pigment { color rgb <0.9, 0.5, 0.9> }
  finish { phong 0.8 }
  rotate <0, 50, 0> translate <3, 1.0, 0>
}
merge {
  sphere { <-0.35, 0.5, 0>, 0.5 pigment { color rgb <0.95, 0.5, 0.1> } }
  sphere { <0.35, 0.5, 0>, 0.5 pigment { color rgb <0.1, 0.6, 0.9> } }
  translate <-1.3, 0, -2.6>
}
intersection {
  plane { y, 0.25 }
  box { <-0.7, -1, -0.5>, <0.7, 1, 0.5> }
  sphere { <0, 0.25, 0>, 0.65 inverse }
  pigment { color rgb <0.85, 0.85, 0.3> }
  translate <1.5, 0, -2.8>
}
intersection {
  sphere { <0, 0.7, 0>, 0.7 }
  disc { <0, 0.7, 0>, <1, 1, 0>, 5 }
  pigment { color rgb <0.95, 0.3, 0.3> }
  translate <3.5, 0, 3>
}
difference {
  cylinder { <0, 0, 0>, <0, 1.2, 0>, 0.6 }
  cylinder { <0, 0.3, 0>, <0, 2, 0>, 0.45 open pigment { color rgb <0.3, 0.3, 0.3> } }
  pigment { color rgb <0.6, 0.4, 0.25> }
  translate <-3.5, 0, 3.2>
}
