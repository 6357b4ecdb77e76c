// Worst case "fan" (docs/performance.md, "Worst cases"): pixels crossed by
// dozens of edges. A sunburst of 96 thin triangles in two colours meets at
// one point in the middle of the image, so the pixels about it hold up to
// 96 edges; to its right a bundle of 24 parallel wires, all within one
// pixel's width at 120 x 90, in front of a wall. Flat shading (ambient 1):
// the truth is coverage.
//   asos render examples/bench/worst_fan.pov -W 120 -H 90 -o fan.png
//   asos-bench accuracy examples/bench/worst_fan.pov -W 120 -H 90 -o build/worst
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.1, 0.1, 0.15> }
camera { location <0, 0, -10> look_at <0, 0, 0> angle 60 }
#declare Dark = texture { pigment { color rgb <0.1, 0.2, 0.6> } finish { ambient 1 diffuse 0 } }
#declare Light = texture { pigment { color rgb <1, 0.85, 0.4> } finish { ambient 1 diffuse 0 } }

#declare Rays = 96;
#for (K, 0, Rays - 1)
  #declare A0 = 2 * pi * K / Rays;
  #declare A1 = 2 * pi * (K + 1) / Rays;
  polygon { 4, <-1.5, 0, 0>, <-1.5 + 4 * cos(A0), 4 * sin(A0), 0>, <-1.5 + 4 * cos(A1), 4 * sin(A1), 0>, <-1.5, 0, 0>
    texture { #if (mod(K, 2) = 0) Dark #else Light #end } }
#end

// 24 wires 0.002 thick, 0.003 apart: the bundle is 0.07 wide, under a pixel (0.096 at z = 0).
#for (K, 0, 23)
  cylinder { <3.2 + K * 0.003, -3, -0.5>, <3.6 + K * 0.003, 3, -0.5>, 0.001 texture { Light } }
#end
plane { z, 1 texture { Dark } }
