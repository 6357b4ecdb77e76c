// Worst case "grazing" (docs/performance.md, "Worst cases"): a plane seen at
// a grazing angle. The eye is 2 cm above a floor that runs to the horizon,
// where each pixel's footprint on the floor is kilometres long; boxes and a
// disc stand on the floor (surfaces in contact at a grazing angle) and a
// sphere rests on it, touching it at one point. Lit by a point light low in
// the sky, so the floor's brightness changes across its footprints.
//   asos render examples/bench/worst_grazing.pov -W 120 -H 90 -o grazing.png
//   asos-bench accuracy examples/bench/worst_grazing.pov -W 120 -H 90 -o build/worst
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.5, 0.65, 0.9> }
camera { location <0, 0.02, -3> look_at <0, 0.05, 0> angle 60 }
light_source { <-30, 8, 10>, color rgb 1 }
#declare Matte = finish { ambient 0.2 diffuse 0.8 }
plane { y, 0 pigment { color rgb <0.6, 0.55, 0.45> } finish { Matte } }
box { <-1.2, 0, 0>, <-0.8, 0.3, 0.4> pigment { color rgb <0.8, 0.3, 0.2> } finish { Matte } }
box { <0.4, 0, 2>, <1.4, 0.08, 2.6> rotate y * 20 pigment { color rgb <0.2, 0.6, 0.3> } finish { Matte } }
disc { <-0.2, 0.0005, 1>, y, 0.6 pigment { color rgb <0.9, 0.9, 0.8> } finish { Matte } }
sphere { <0.6, 0.15, 0.3>, 0.15 pigment { color rgb <0.3, 0.4, 0.9> } finish { Matte } }
