// Cross-check of area lights against POV-Ray 3.7: primitives before a wall
// under one area light. Switches (declared on the command line):
//   Light        1 a horizontal 3 x 1.5 rectangular light (default),
//                2 a linear light 3 long, 3 a circular orient light 1.5 across;
//   Adaptive     POV-Ray's adaptive level, or -1 for none (default);
//   Illumination 1 for area_illumination;
//   Samples      the lattice's points along the first axis (default 9; the
//                rectangle has (Samples + 1) / 2 along its second).
// Rendered by tests/unit/render_golden_test.cpp; POV-Ray's references by
// scripts/update-goldens.sh (the test's options and declarations).
#version 3.7;
#ifndef (Light) #declare Light = 1; #end
#ifndef (Adaptive) #declare Adaptive = -1; #end
#ifndef (Illumination) #declare Illumination = 0; #end
#ifndef (Samples) #declare Samples = 9; #end
global_settings { assumed_gamma 1.0 }
background { color rgb <0.1, 0.1, 0.15> }
camera { location <0, 2.2, -7> look_at <0, 1.4, 0> angle 50 }
light_source {
  <0, 4.5, -1.5>, color rgb 1
  #if (Light = 2)
    area_light <3, 0, 0>, <0, 0, 0>, Samples, 1
  #elseif (Light = 3)
    area_light <1.5, 0, 0>, <0, 0, 1.5>, Samples, Samples circular orient
  #else
    area_light <3, 0, 0>, <0, 0, 1.5>, Samples, (Samples + 1) / 2
  #end
  #if (Adaptive >= 0) adaptive Adaptive #end
  #if (Illumination) area_illumination #end
}
#declare Matte = finish { ambient 0.1 diffuse 0.8 }
plane { y, 0 pigment { color rgb 0.8 } finish { Matte } }
plane { z, 1 pigment { color rgb <0.9, 0.85, 0.7> } finish { Matte } }
sphere { <-1.4, 0.7, -0.6>, 0.7 pigment { color rgb <0.8, 0.2, 0.2> } finish { Matte phong 0.6 phong_size 20 } }
box { <-0.4, 0, -0.4>, <0.4, 1.6, 0.4> rotate <0, 30, 0> translate <0.3, 0, 0.1>
  pigment { color rgb <0.2, 0.4, 0.8> } finish { Matte specular 0.4 roughness 0.05 } }
cylinder { <1.3, 0, -0.9>, <1.3, 1.1, -0.9>, 0.35 pigment { color rgb <0.2, 0.7, 0.3> } finish { Matte } }
disc { <1.6, 1.9, 0.2>, <0.3, 1, -0.5>, 0.45 pigment { color rgb <0.6, 0.3, 0.8> } finish { Matte } }
