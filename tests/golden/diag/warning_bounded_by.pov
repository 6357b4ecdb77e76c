// bounded_by where POV-Ray's image would differ from asos's clip: a union
// reaching out of its bound (POV-Ray keeps the bound of a CSG and shows what
// lies outside it on the rays that meet it), a plane with a bound (POV-Ray
// drops it but takes its box), a sphere with a smaller bound box (the same).
// No warning for a bound that holds its object, or a larger one.
#version 3.7;
global_settings { assumed_gamma 1 }
union { sphere { 0, 1 } sphere { x, 1 } bounded_by { box { -1, 1 } } }
plane { y, 0 bounded_by { sphere { 0, 10 } } }
sphere { 0, 1 bounded_by { box { <-0.5, -0.5, -2>, <0.5, 0.5, 2> } } }
union { sphere { 0, 1 } sphere { x, 1 } bounded_by { box { <-1, -1, -1>, <2, 1, 1> } } }
sphere { 0, 1 bounded_by { box { -2, 2 } } }
intersection { plane { x, 1 } plane { -x, 1 } plane { y, 1 } plane { -y, 1 } plane { z, 1 } plane { -z, 1 }
  bounded_by { sphere { 0, 1.74 } } }
#declare Held = union { sphere { 0, 1 } bounded_by { box { -0.5, 0.5 } } }
object { Held }
object { Held translate x }
