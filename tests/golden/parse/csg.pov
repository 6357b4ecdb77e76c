// CSG: difference, intersection, merge, inverse, a union inside a
// difference; members keep their textures, the CSG's goes to those without;
// transforms apply to the whole.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.5, 0> }
light_source { <5, 10, -5>, rgb 1 }
difference {
  box { -1, 1 pigment { rgb <0, 0, 1> } }
  union {
    sphere { <0, 1, 0>, 0.5 }
    cylinder { -2*x, 2*x, 0.25 pigment { rgb <1, 0, 0> } inverse inverse }
  }
  pigment { rgb <0, 1, 0> }
  rotate 30*y
  translate <-2, 0, 0>
}
intersection {
  sphere { -0.5*x, 1 }
  sphere { 0.5*x, 1 inverse }
  plane { y, 0.2 }
  scale 0.5
}
merge {
  sphere { 0, 1 }
  box { 0, 1 }
  light_source { <0, 3, 0>, rgb 0.5 }
  translate <2, 0, 0>
  no_shadow
}
union {
  sphere { 0, 0.5 }
  sphere { y, 0.5 }
  inverse
  translate <0, 0, 3>
}
