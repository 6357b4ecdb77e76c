// Cross-check of POV-Ray's clipped_by and bounded_by: a sphere clipped by a
// box (its inside seen through the cuts), a plane clipped to a disc by a
// cylinder, a difference clipped by an inverted plane, a union clipped by
// clipped_by { bounded_by }, an octahedron of planes bounded by a sphere
// (POV-Ray keeps that bound: it holds the octahedron). Rendered by
// tests/unit/render_golden_test.cpp with one ray per pixel; POV-Ray's
// reference by scripts/update-goldens.sh (povray -A).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -7> look_at <0, 0.5, 0> angle 60 }
light_source { <4, 8, -6> color rgb 1 }
plane { y, -1 pigment { checker rgb 0.8 rgb 0.5 } }
sphere { <-2.4, 0.4, 0>, 1 pigment { rgb <0.9, 0.3, 0.2> }
  clipped_by { box { <-3.2, -0.4, -0.7>, <-1.6, 1.2, 0.7> } } }
plane { z, 0 pigment { rgb <0.2, 0.5, 0.9> } rotate x * -60
  clipped_by { cylinder { <0, -1, 0>, <0, 2, 0>, 0.8 } } translate <0, 0.3, 2> }
difference { box { -0.7, 0.7 } sphere { 0, 0.85 } pigment { rgb <0.9, 0.8, 0.3> }
  clipped_by { plane { y, 0.2 inverse } } rotate y * 30 translate <0.1, 0, -0.6> }
union { sphere { <0, 0, 0>, 0.6 } sphere { <0.5, 0.4, 0>, 0.5 } pigment { rgb <0.3, 0.8, 0.4> }
  bounded_by { box { <-0.6, -0.6, -0.6>, <1.0, 0.5, 0.6> } } clipped_by { bounded_by } translate <2.3, 0, 0.4> }
intersection {
  plane { z, 1 rotate <35.26438968275, 0, 0> } plane { z, 1 rotate <-35.26438968275, 0, 0> }
  plane { -z, 1 rotate <35.26438968275, 0, 0> } plane { -z, 1 rotate <-35.26438968275, 0, 0> }
  plane { x, 1 rotate <0, 0, -35.26438968275> } plane { x, 1 rotate <0, 0, 35.26438968275> }
  plane { -x, 1 rotate <0, 0, -35.26438968275> } plane { -x, 1 rotate <0, 0, 35.26438968275> }
  bounded_by { sphere { 0, 1.8 } }
  pigment { rgb <0.7, 0.4, 0.9> } scale 0.5 translate <-0.9, -0.2, -2.2> }
