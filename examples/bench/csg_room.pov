// A room built with CSG (issue 22): a wall with a window cut out, a table
// whose top has a round cut-out and a slot, a box with holes through it along
// three axes, a lens (the intersection of two spheres), a bowl (a hemisphere
// hollowed by a smaller one), and a merge of spheres, under a rectangular
// area light. It renders the same way in POV-Ray 3.7; LightN sets the area
// light's points along each side (POV-Ray's n1 = n2):
//   asos render examples/bench/csg_room.pov -o csg_room.png
//   povray +Iexamples/bench/csg_room.pov +Ocsg_room-pov.png +W320 +H240 Declare=LightN=9
// scripts/bench-scenes.sh times both against a converged POV-Ray render.
#version 3.7;
#ifndef (LightN) #declare LightN = 5; #end
#ifndef (LightAdaptive) #declare LightAdaptive = 1; #end
global_settings { assumed_gamma 1.0 }
camera { location <2.0, 2.1, -2.4> look_at <-0.6, 0.6, 1.2> angle 68 }
light_source {
  <0.3, 2.8, 0.4>, color rgb 1.1
  area_light <0.8, 0, 0>, <0, 0, 0.8>, LightN, LightN
  adaptive LightAdaptive
}
light_source { <2.5, 2.5, -2.5>, color rgb 0.25 shadowless }

#declare Matte = finish { ambient 0.15 diffuse 0.7 }
#declare Wall = texture { pigment { color rgb <0.86, 0.84, 0.78> } finish { Matte } }
#declare Wood = texture { pigment { color rgb <0.55, 0.36, 0.2> } finish { ambient 0.15 diffuse 0.7 phong 0.3 phong_size 30 } }
#declare Metal = texture { pigment { color rgb 0.6 } finish { ambient 0.1 diffuse 0.5 specular 0.6 roughness 0.02 } }

plane { y, 0
  pigment { checker color rgb <0.72, 0.6, 0.45>, color rgb <0.45, 0.33, 0.22> scale 0.5 }
  finish { Matte } }
plane { y, 3 texture { Wall } }
// The back wall with a window: its reveal shows the cut's own texture.
difference {
  box { <-3, 0, 3>, <3, 3, 3.15> texture { Wall } }
  box { <-2.2, 1.0, 2.9>, <-0.8, 2.3, 3.3> texture { Wood } }
}
box { <-3.15, 0, -3>, <-3, 3, 3.15> texture { Wall } }
box { <3, 0, -3>, <3.15, 3, 3.15> texture { Wall } }

// The table: a top with a round hole and a slot cut, four legs.
difference {
  box { <-1.6, 0.72, 0.6>, <0.4, 0.78, 1.8> }
  cylinder { <-0.2, 0.6, 1.2>, <-0.2, 0.9, 1.2>, 0.22 }
  box { <-1.3, 0.6, 0.5>, <-1.1, 0.9, 1.1> }
  texture { Wood }
}
#declare Leg = cylinder { <0, 0, 0>, <0, 0.72, 0>, 0.04 texture { Wood } }
object { Leg translate <-1.5, 0, 0.7> }
object { Leg translate <0.3, 0, 0.7> }
object { Leg translate <-1.5, 0, 1.7> }
object { Leg translate <0.3, 0, 1.7> }

// A box with holes through it along three axes.
difference {
  box { -0.25, 0.25 }
  cylinder { -0.4*x, 0.4*x, 0.12 }
  cylinder { -0.4*y, 0.4*y, 0.12 }
  cylinder { -0.4*z, 0.4*z, 0.12 pigment { color rgb <0.9, 0.2, 0.15> } }
  pigment { color rgb <0.25, 0.45, 0.85> }
  finish { ambient 0.15 diffuse 0.7 phong 0.4 }
  rotate <0, 35, 0>
  translate <1.2, 0.25, 0.2>
}
// A lens on the table.
intersection {
  sphere { <0, 0, -0.35>, 0.45 }
  sphere { <0, 0, 0.35>, 0.45 }
  pigment { color rgb <0.85, 0.5, 0.85> }
  finish { ambient 0.15 diffuse 0.6 phong 0.8 }
  rotate <0, 60, 0>
  translate <-1.4, 1.065, 1.45>
}
// A bowl: a hemisphere hollowed out.
difference {
  sphere { 0, 0.3 }
  sphere { 0, 0.26 pigment { color rgb <0.95, 0.9, 0.6> } }
  plane { -y, 0 }
  texture { Metal }
  translate <-0.7, 1.08, 1.3>
}
// A merge of three spheres on the floor.
merge {
  sphere { <0, 0.2, 0>, 0.2 }
  sphere { <0.25, 0.2, 0>, 0.2 }
  sphere { <0.12, 0.38, 0>, 0.16 }
  pigment { color rgb <0.3, 0.75, 0.35> }
  finish { ambient 0.15 diffuse 0.7 phong 0.5 }
  translate <-2.0, 0, -0.6>
}
