// Cross-check of spotlights, cylinder lights and parallel lights against
// POV-Ray 3.7: a floor and a wall with a few objects, under
//   a white spotlight (radius 12, falloff 20, tightness 10) on the floor,
//     its soft edge between the two cones crossing the sphere;
//   a red spotlight with POV-Ray's defaults (radius 30, falloff 45,
//     tightness 0) on the wall;
//   a blue cylinder light (radius 0.5, falloff 0.9, tightness 2) down
//     over the box's corner, with its shadow;
//   a dim parallel light from the side (shadows along its axis).
// Switch (declared on the command line): Area 1 gives the white spotlight a
// 5 x 5 area light (POV-Ray's lights/arealit*.pov: area_light + spotlight).
// Rendered by tests/unit/render_golden_test.cpp; POV-Ray's references by
// scripts/update-goldens.sh (the test's options and declarations).
#version 3.7;
#ifndef (Area) #declare Area = 0; #end
global_settings { assumed_gamma 1.0 }
background { color rgb <0.05, 0.05, 0.08> }
camera { location <0, 3, -7> look_at <0, 0.8, 0> angle 55 }
#declare Matte = finish { ambient 0.05 diffuse 0.8 }
light_source {
  <-1, 6, -2>, color rgb 1.2
  spotlight point_at <-0.6, 0, 0> radius 12 falloff 20 tightness 10
  #if (Area) area_light <1, 0, 0>, <0, 0, 1>, 5, 5 #end
}
light_source { <3, 3, -3>, color rgb <0.8, 0.25, 0.15> spotlight point_at <1.8, 1.8, 1> }
light_source {
  <1.6, 5, -0.6>, color rgb <0.3, 0.5, 1.5>
  cylinder point_at <1.9, 0, -0.9> radius 0.5 falloff 0.9 tightness 2
}
light_source { <-8, 3, 1>, color rgb 0.25 parallel point_at <0, 0, 0> }
plane { y, 0 pigment { color rgb 0.8 } finish { Matte } }
plane { z, 1 pigment { color rgb <0.9, 0.85, 0.7> } finish { Matte } }
sphere { <-0.9, 0.6, -0.4>, 0.6 pigment { color rgb <0.8, 0.8, 0.3> } finish { Matte phong 0.5 phong_size 30 } }
box { <-0.3, 0, -0.3>, <0.3, 1.2, 0.3> rotate <0, 20, 0> translate <1.3, 0, -0.3>
  pigment { color rgb <0.9, 0.9, 0.9> } finish { Matte specular 0.4 roughness 0.05 } }
