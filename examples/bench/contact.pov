// Objects in contact and overlapping (the stand-in for CSG that users build
// without it) in front of a wall, under a horizontal 3 x 1.5 rectangular area
// light. It stresses surfaces that touch or cross: objects standing on a
// table and on the floor, boxes stacked, spheres sunk into boxes, a cylinder
// through a sphere, a disc lying flat on the table, the wall meeting the floor;
// and the penumbrae they cast on one another and on the wall.
// It renders the same way in POV-Ray 3.7; LightN sets the light's points:
//   asos render examples/bench/contact.pov -o contact.png
//   povray +Iexamples/bench/contact.pov +Ocontact-pov.png +W320 +H240 Declare=LightN=9
// scripts/bench-scenes.sh times both against a converged POV-Ray render.
#version 3.7;
#ifndef (LightN) #declare LightN = 5; #end
#ifndef (LightAdaptive) #declare LightAdaptive = 1; #end

global_settings { assumed_gamma 1.0 }
camera { location <0.5, 2.4, -5.5> look_at <0, 0.9, 0.5> angle 50 }
light_source {
  <-0.5, 4, -1.5>, color rgb 1
  area_light <3, 0, 0>, <0, 0, 1.5>, LightN, LightN
  adaptive LightAdaptive
}

#declare Matte = finish { ambient 0.12 diffuse 0.75 }
#declare Glossy = finish { ambient 0.12 diffuse 0.65 phong 0.6 phong_size 60 }
plane { y, 0 pigment { color rgb <0.75, 0.72, 0.65> } finish { Matte } }
box { <-6, 0, 2>, <6, 5, 2.2> pigment { color rgb <0.85, 0.85, 0.9> } finish { Matte } }

// A table standing on the floor, its top touching its legs.
box { <-1.6, 0.8, -0.6>, <1.6, 0.88, 1.0> pigment { color rgb <0.5, 0.32, 0.18> } finish { Glossy } }
#declare Leg = box { <-0.05, 0, -0.05>, <0.05, 0.8, 0.05> pigment { color rgb <0.45, 0.3, 0.16> } finish { Matte } }
object { Leg translate <-1.5, 0, -0.5> }
object { Leg translate <1.5, 0, -0.5> }
object { Leg translate <-1.5, 0, 0.9> }
object { Leg translate <1.5, 0, 0.9> }

// On the table: stacked boxes, a sphere sunk into a box, a cylinder through a
// sphere, a cone on a disc, a ball resting on the top.
box { <-1.4, 0.88, -0.3>, <-0.8, 1.18, 0.3> pigment { color rgb <0.2, 0.4, 0.85> } finish { Glossy } }
box { <-1.3, 1.18, -0.2>, <-0.9, 1.48, 0.2> rotate y*0 pigment { color rgb <0.85, 0.3, 0.2> } finish { Glossy } }
box { <-0.45, 0.88, -0.25>, <0.05, 1.2, 0.25> pigment { color rgb <0.9, 0.8, 0.3> } finish { Matte } }
sphere { <-0.2, 1.25, 0.0>, 0.22 pigment { color rgb <0.3, 0.7, 0.4> } finish { Glossy } }
sphere { <0.55, 1.2, 0.1>, 0.3 pigment { color rgb <0.8, 0.5, 0.7> } finish { Glossy } }
cylinder { <0.15, 1.1, 0.1>, <0.95, 1.3, 0.1>, 0.07 pigment { color rgb 0.85 } finish { Glossy } }
disc { <1.2, 0.8805, 0.4>, y, 0.3 pigment { color rgb <0.2, 0.2, 0.25> } finish { Matte } }
cone { <1.2, 0.8805, 0.4>, 0.22, <1.2, 1.5, 0.4>, 0 pigment { color rgb <0.95, 0.6, 0.1> } finish { Matte } }
sphere { <1.0, 0.98, -0.35>, 0.1 pigment { color rgb <0.9, 0.15, 0.15> } finish { Glossy } }

// On the floor: boxes against the wall and a sphere half sunk into the floor.
box { <-2.8, 0, 1.4>, <-2.0, 0.6, 2.0> rotate y*0 pigment { color rgb <0.6, 0.6, 0.3> } finish { Matte } }
box { <-2.6, 0.6, 1.5>, <-2.1, 0.9, 2.0> pigment { color rgb <0.3, 0.55, 0.6> } finish { Matte } }
sphere { <2.3, 0, 0.8>, 0.5 pigment { color rgb <0.3, 0.3, 0.8> } finish { Glossy } }
cylinder { <1.8, 0, 1.6>, <1.8, 1.6, 1.6>, 0.15 pigment { color rgb <0.7, 0.7, 0.7> } finish { Glossy } }
sphere { <1.8, 1.6, 1.6>, 0.25 pigment { color rgb <0.8, 0.75, 0.2> } finish { Glossy } }
