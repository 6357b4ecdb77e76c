// Benchmark scene "checker" (docs/performance.md): a checkered plane to the
// horizon under a sky. Near the camera the squares cover many pixels and
// only their edges need samples; toward the horizon more and more squares
// fall into one pixel, where every method's error goes to their mean (a
// flat grey) only as fast as its samples resolve them. Pattern edges cross
// pixels that one object covers, which object-space adaptive sampling sees
// only through its pattern options (--pattern-edges, --pattern-filter).
//   asos render examples/bench/checker.pov -W 320 -H 240 -o checker.png
//   asos-bench accuracy examples/bench/checker.pov -o build/accuracy
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.55, 0.7, 0.9> }
camera { location <0, 1.5, -6> look_at <0, 0.9, 0> angle 70 }
light_source { <-20, 40, -30>, color rgb 1 }
plane { y, 0
  pigment { checker color rgb 0.92, color rgb <0.12, 0.15, 0.25> scale 0.5 rotate y * 17 }
  finish { ambient 0.25 diffuse 0.75 } }
