// Worst case "sub-thin" (docs/performance.md, "Worst cases"): objects
// thinner than a square of MAX 4 (1/16 pixel), which ASOS finds by their
// cones but which no lattice point need hit. At 120 x 90 (0.1 unit a pixel
// on z = 0): wires 0.01 to 0.06 pixel wide at several slopes and spheres
// 0.02 to 0.06 pixel across, white in ambient light on black, so each one's
// true brightness is its area in pixels.
//   asos render examples/bench/worst_subthin.pov -W 120 -H 90 -o subthin.png
//   asos-bench accuracy examples/bench/worst_subthin.pov -W 120 -H 90 -o build/worst
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb 0 }
camera { location <0, 0, -10> look_at <0, 0, 0> angle 61.9275 }   // 12 units wide at z = 0
#declare Flat = texture { pigment { color rgb 1 } finish { ambient 1 diffuse 0 } }

#for (I, 0, 9)
  #declare W = 0.001 + 0.005 * I / 9;          // 0.01 to 0.06 pixel
  cylinder { <-5.5, 4 - 0.5 * I, 0>, <5.5, 4 - 0.5 * I + (I - 4.5) * 0.3, 0>, W / 2 texture { Flat } }
#end
#for (I, 0, 19)
  #declare D = 0.002 + 0.004 * I / 19;         // 0.02 to 0.06 pixel across
  sphere { <-5.2 + 0.55 * I, -2.5 - 0.1 * mod(I, 3), 0>, D / 2 texture { Flat } }
  sphere { <-5.1 + 0.55 * I, -3.6, 0>, D / 3 texture { Flat } }
#end
