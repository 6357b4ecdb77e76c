// An office in the spirit of the paper's Figure 8 (Genetti & Gordon 1993): the
// kind of scene people build, and where ray tracers waste work. It stresses
//   * surfaces in contact: walls, baseboards and furniture standing on the
//     floor, books standing side by side, objects resting on the desk;
//   * decals: a rug 2 mm above the floor, papers 0.5 mm above the desk,
//     pictures 1 mm in front of a wall;
//   * a rectangular area light just under the ceiling (an object beyond the
//     light cannot shadow it);
//   * a textured floor (a checker to the far wall) and a mirror.
// 84 objects; it renders the same way in POV-Ray 3.7. LightN sets the area
// light's points along each side (POV-Ray's n1 = n2):
//   asos render examples/bench/room.pov -o room.png
//   povray +Iexamples/bench/room.pov +Oroom-pov.png +W320 +H240 Declare=LightN=9
// scripts/bench-scenes.sh times both against a converged POV-Ray render.
#version 3.7;
#ifndef (LightN) #declare LightN = 5; #end
#ifndef (LightAdaptive) #declare LightAdaptive = 1; #end

global_settings { assumed_gamma 1.0 }
camera { location <2.4, 1.65, -2.8> look_at <-1.0, 0.8, 1.3> angle 70 }

light_source {
  <0, 2.9, 0.9>, color rgb 1.1
  area_light <1.2, 0, 0>, <0, 0, 0.6>, LightN, LightN
  adaptive LightAdaptive
}

#declare Matte = finish { ambient 0.15 diffuse 0.7 }
#declare Wall = texture { pigment { color rgb <0.86, 0.84, 0.78> } finish { Matte } }
#declare Wood = texture { pigment { color rgb <0.55, 0.36, 0.2> } finish { ambient 0.15 diffuse 0.7 phong 0.3 phong_size 30 } }
#declare Metal = texture { pigment { color rgb 0.6 } finish { ambient 0.1 diffuse 0.5 specular 0.6 roughness 0.02 } }

// The room: a checkered floor, a ceiling above the light, four walls standing on the floor.
plane { y, 0
  pigment { checker color rgb <0.72, 0.6, 0.45>, color rgb <0.45, 0.33, 0.22> scale 0.5 }
  finish { Matte } }
plane { y, 3 texture { Wall } }
box { <-3, 0, 4>, <3, 3, 4.1> texture { Wall } }
box { <-3.1, 0, -3>, <-3, 3, 4.1> texture { Wall } }
box { <3, 0, -3>, <3.1, 3, 4.1> texture { Wall } }
box { <-3, 0, -3.1>, <3, 3, -3> texture { Wall } }
// Baseboards, touching wall and floor.
box { <-3, 0, 3.97>, <3, 0.1, 4> texture { Wood } }
box { <-3, 0, -3>, <-2.97, 0.1, 4> texture { Wood } }
box { <2.97, 0, -3>, <3, 0.1, 4> texture { Wood } }
// The light's fitting, flush with the ceiling above the light.
box { <-0.7, 2.95, 0.55>, <0.7, 3, 1.25> texture { Metal } }

// A rug, 2 mm above the floor, and a low table on it.
disc { <0.4, 0.002, 0.6>, y, 1.3 pigment { color rgb <0.6, 0.12, 0.1> } finish { Matte } }
disc { <0.4, 0.003, 0.6>, y, 1.1, 1.0 pigment { color rgb <0.85, 0.7, 0.3> } finish { Matte } }
cylinder { <0.4, 0.002, 0.6>, <0.4, 0.38, 0.6>, 0.06 texture { Metal } }
cylinder { <0.4, 0.38, 0.6>, <0.4, 0.42, 0.6>, 0.55 texture { Wood } }
cylinder { <0.3, 0.42, 0.5>, <0.3, 0.52, 0.5>, 0.04 pigment { color rgb 0.9 } finish { ambient 0.15 diffuse 0.6 phong 0.6 } }
cylinder { <0.55, 0.42, 0.7>, <0.55, 0.52, 0.7>, 0.04 pigment { color rgb <0.2, 0.4, 0.8> } finish { ambient 0.15 diffuse 0.6 phong 0.6 } }
sphere { <0.45, 0.52, 0.3>, 0.1 pigment { color rgb <0.9, 0.6, 0.1> } finish { ambient 0.15 diffuse 0.6 phong 0.5 } }

// The desk against the back wall, and what stands on it.
box { <-2.2, 0.72, 2.9>, <0.0, 0.76, 3.9> texture { Wood } }
box { <-2.15, 0, 2.95>, <-2.08, 0.72, 3.02> texture { Wood } }
box { <-0.12, 0, 2.95>, <-0.05, 0.72, 3.02> texture { Wood } }
box { <-2.15, 0, 3.78>, <-2.08, 0.72, 3.85> texture { Wood } }
box { <-0.12, 0, 3.78>, <-0.05, 0.72, 3.85> texture { Wood } }
box { <-2.1, 0.4, 3.75>, <-0.07, 0.72, 3.8> texture { Wood } }
// Papers, 0.5 mm thick, lying on the desk.
box { <-0.15, 0, -0.105>, <0.15, 0.0005, 0.105> rotate y*12 translate <-1.55, 0.76, 3.2>
  pigment { color rgb 0.97 } finish { Matte } }
box { <-0.15, 0, -0.105>, <0.15, 0.0005, 0.105> rotate -y*7 translate <-1.35, 0.7605, 3.25>
  pigment { color rgb 0.93 } finish { Matte } }
box { <-0.105, 0, -0.15>, <0.105, 0.0005, 0.15> rotate y*30 translate <-0.5, 0.76, 3.15>
  pigment { color rgb <0.95, 0.95, 0.8> } finish { Matte } }
// A monitor on a stand, a lamp, a mug and a ball resting on the desk.
box { <-1.1, 0.76, 3.55>, <-0.9, 0.78, 3.7> texture { Metal } }
box { <-1.03, 0.78, 3.6>, <-0.97, 1.0, 3.64> texture { Metal } }
box { <-1.4, 0.95, 3.55>, <-0.6, 1.45, 3.6> pigment { color rgb 0.08 } finish { ambient 0.1 diffuse 0.4 phong 0.8 phong_size 80 } }
box { <-1.37, 0.98, 3.549>, <-0.63, 1.42, 3.55> pigment { color rgb <0.15, 0.25, 0.45> } finish { ambient 0.4 diffuse 0.2 } }
cylinder { <-0.3, 0.76, 3.5>, <-0.3, 0.78, 3.5>, 0.1 texture { Metal } }
cylinder { <-0.3, 0.78, 3.5>, <-0.3, 1.15, 3.5>, 0.012 texture { Metal } }
cone { <-0.3, 1.1, 3.5>, 0.14, <-0.3, 1.25, 3.5>, 0.05 open pigment { color rgb <0.2, 0.5, 0.3> } finish { Matte } }
cylinder { <-1.8, 0.76, 3.15>, <-1.8, 0.86, 3.15>, 0.04 pigment { color rgb <0.8, 0.2, 0.2> } finish { ambient 0.15 diffuse 0.6 phong 0.6 } }
sphere { <-0.6, 0.82, 3.0>, 0.06 pigment { color rgb <0.2, 0.6, 0.9> } finish { ambient 0.15 diffuse 0.6 phong 0.7 } }
// Books standing side by side on the desk.
#declare I = 0;
#while (I < 6)
  box { <-2.1 + I * 0.045, 0.76, 3.6>, <-2.055 + I * 0.045, 0.98 + mod(I, 3) * 0.02, 3.8>
    pigment { color rgb <0.2 + 0.14 * mod(I * 3, 5), 0.15 + 0.15 * mod(I * 2, 4), 0.2 + 0.2 * mod(I, 3)> } finish { Matte } }
  #declare I = I + 1;
#end

// A chair in front of the desk.
box { <-1.5, 0.44, 2.0>, <-1.0, 0.48, 2.5> texture { Wood } }
box { <-1.5, 0.48, 1.96>, <-1.0, 0.95, 2.0> texture { Wood } }
cylinder { <-1.47, 0, 2.03>, <-1.47, 0.44, 2.03>, 0.02 texture { Metal } }
cylinder { <-1.03, 0, 2.03>, <-1.03, 0.44, 2.03>, 0.02 texture { Metal } }
cylinder { <-1.47, 0, 2.47>, <-1.47, 0.44, 2.47>, 0.02 texture { Metal } }
cylinder { <-1.03, 0, 2.47>, <-1.03, 0.44, 2.47>, 0.02 texture { Metal } }

// A bookshelf against the left wall, its shelves full of books.
box { <-3, 0, 0.0>, <-2.6, 1.9, 0.03> texture { Wood } }
box { <-3, 0, 1.47>, <-2.6, 1.9, 1.5> texture { Wood } }
#declare S = 0;
#while (S < 4)
  box { <-3, 0.05 + S * 0.6, 0.03>, <-2.6, 0.08 + S * 0.6, 1.47> texture { Wood } }
  #if (S < 3)
    #declare J = 0;
    #while (J < 4)
      box { <-2.95, 0.08 + S * 0.6, 0.1 + J * 0.33>, <-2.68, 0.36 + S * 0.6 + mod(J + S, 2) * 0.05, 0.38 + J * 0.33>
        pigment { color rgb <0.2 + 0.14 * mod(J * 3 + S, 5), 0.15 + 0.15 * mod(J * 2 + S, 4), 0.2 + 0.2 * mod(J + S, 3)> } finish { Matte } }
      #declare J = J + 1;
    #end
  #end
  #declare S = S + 1;
#end

// A mirror on the left wall, its frame on the wall, the glass 1 mm in front of the frame.
box { <-3, 0.85, -1.5>, <-2.97, 2.25, -0.2> texture { Wood } }
box { <-2.97, 0.9, -1.45>, <-2.969, 2.2, -0.25>
  pigment { color rgb 0.02 } finish { ambient 0 diffuse 0.05 reflection 0.85 } }

// Pictures hung 1 mm in front of the back wall, and one on the left wall.
polygon { 5, <-0.6, 1.5>, <0.3, 1.5>, <0.3, 2.2>, <-0.6, 2.2>, <-0.6, 1.5> translate z*3.999
  pigment { color rgb <0.9, 0.85, 0.7> } finish { Matte } }
polygon { 5, <-0.52, 1.58>, <0.22, 1.58>, <0.22, 2.12>, <-0.52, 2.12>, <-0.52, 1.58> translate z*3.998
  pigment { checker color rgb <0.3, 0.5, 0.7>, color rgb <0.8, 0.6, 0.3> scale 0.09 } finish { Matte } }
polygon { 5, <1.0, 1.3>, <2.0, 1.3>, <2.0, 2.0>, <1.0, 2.0>, <1.0, 1.3> translate z*3.999
  pigment { color rgb <0.2, 0.25, 0.2> } finish { Matte } }
disc { <1.5, 1.65, 3.998>, -z, 0.25 pigment { color rgb <0.9, 0.8, 0.2> } finish { Matte } }
polygon { 5, <2.2, 1.2>, <3.2, 1.2>, <3.2, 1.9>, <2.2, 1.9>, <2.2, 1.2> rotate y*-90 translate x*-2.999
  pigment { color rgb <0.3, 0.45, 0.3> } finish { Matte } }

// A plant in a pot, standing on the floor in a corner.
cone { <2.4, 0, 3.4>, 0.16, <2.4, 0.45, 3.4>, 0.22 pigment { color rgb <0.7, 0.35, 0.2> } finish { Matte } }
disc { <2.4, 0.43, 3.4>, y, 0.2 pigment { color rgb <0.25, 0.15, 0.08> } finish { Matte } }
cylinder { <2.4, 0.43, 3.4>, <2.4, 1.0, 3.4>, 0.02 pigment { color rgb <0.3, 0.5, 0.2> } finish { Matte } }
sphere { <2.4, 1.15, 3.4>, 0.28 pigment { color rgb <0.2, 0.55, 0.2> } finish { Matte } }
sphere { <2.25, 0.95, 3.3>, 0.18 pigment { color rgb <0.25, 0.6, 0.25> } finish { Matte } }
sphere { <2.55, 0.9, 3.5>, 0.16 pigment { color rgb <0.18, 0.5, 0.2> } finish { Matte } }
