// Benchmark scene "thin" (docs/performance.md): objects thinner than a pixel,
// which a sample either hits or misses. Sizes in pixels are at 320 x 240 (one
// pixel is 0.1 unit on the plane z = 0, 0.15 on z = 10, 0.2 on z = 20):
//   * wires (cylinders) 0.2 to 1.5 pixels wide at several slopes, on the
//     planes z = 0 and z = 10, some in front of a large box, some behind a
//     large sphere;
//   * spheres 0.3 to 2 pixels across at the depths z = 0, 10 and 20, a row in
//     front of the box and a row partly hidden behind the sphere;
//   * a wall behind everything, so that nothing is seen against the background only.
// One point light, no area light: what is tested is the eye's sampling.
//   asos render examples/bench/thin.pov -W 320 -H 240 -o thin.png
//   asos-bench accuracy examples/bench/thin.pov -o build/accuracy
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.1, 0.1, 0.12> }
camera { location <0, 0, -20> look_at <0, 0, 0> angle 77.3196 }
light_source { <-10, 15, -25>, color rgb 1 }
#declare Flat = finish { ambient 0.25 diffuse 0.75 }

box { <-6, -5, 6>, <4, 5, 8> pigment { color rgb <0.3, 0.45, 0.7> } finish { Flat } }
sphere { <8, 2, 2>, 4 pigment { color rgb <0.75, 0.4, 0.3> } finish { Flat } }
plane { z, 30 pigment { color rgb <0.4, 0.4, 0.38> } finish { Flat } }

// Wires: pixel width w (at z = 0) is 20 * radius; at z = 10, 13.3 * radius.
#for (I, 0, 13)
  #declare R = 0.01 + 0.065 * I / 13;
  #declare S = -0.6 + 0.09 * I;
  cylinder { <-15, 10.5 - 0.5 * I, 0>, <15, 10.5 - 0.5 * I + 30 * S / 4, 0>, R
    pigment { color rgb <0.95, 0.9, 0.6> } finish { Flat } }
  cylinder { <-14 + 2 * I, -14, 10>, <-12 + 2.3 * I, 14, 10>, R * 1.5
    pigment { color rgb <0.6, 0.95, 0.7> } finish { Flat } }
#end

// Spheres 0.3 to 2 pixels across at three depths.
#for (I, 0, 17)
  #declare D = 0.3 + 1.7 * I / 17;
  sphere { <-15 + 1.1 * I, -6, 0>, 0.05 * D pigment { color rgb <1, 0.6, 0.2> } finish { Flat } }
  sphere { <-15 + 1.65 * I, -10, 10>, 0.075 * D pigment { color rgb <0.5, 0.9, 1> } finish { Flat } }
  sphere { <-18 + 2.2 * I, 12, 20>, 0.1 * D pigment { color rgb <1, 0.4, 0.8> } finish { Flat } }
  // In front of the box and behind the big sphere.
  sphere { <-5.5 + 0.5 * I, -3.5 + 0.3 * I, 5>, 0.05 * D pigment { color rgb 1 } finish { Flat } }
  sphere { <5 + 0.35 * I, 3.5 - 0.1 * I, 8>, 0.065 * D pigment { color rgb <1, 1, 0.3> } finish { Flat } }
#end
