// The asos default scene: the six primitives asos renders -- sphere, box,
// cone, cylinder, disc and polygon -- on a checkered plane, lit by one point
// light. It uses only what POV-Ray 3.7 also renders, so the two can be
// compared picture for picture.
//
// With asos:     scripts/render-example.sh
//                (writes build/default.png), or
//                build/asos render examples/default.pov -o default.png
// With POV-Ray:  povray +W640 +H480 +A0.1 examples/default.pov

#version 3.7;

global_settings { assumed_gamma 1.0 }
background { color rgb <0.55, 0.7, 0.9> }

camera {
  location <0, 4.5, -10>
  look_at <0, 0.9, 1>
  angle 48
}

light_source { <-8, 12, -10>, color rgb 1 }

plane {
  y, 0
  pigment { checker color rgb 0.85, color rgb 0.3 }
  finish { diffuse 0.8 }
}

#declare Shiny = finish { phong 0.6 phong_size 60 }

// Front row: sphere, box, cone.
sphere {
  <-3, 1, 0>, 1
  pigment { color rgb <0.85, 0.15, 0.12> }
  finish { Shiny }
}
box {
  <-0.8, 0, -0.8>, <0.8, 1.6, 0.8>
  rotate <0, 30, 0>
  pigment { color rgb <0.2, 0.45, 0.85> }
  finish { Shiny }
}
cone {
  <3, 0, 0>, 1, <3, 2.2, 0>, 0
  pigment { color rgb <0.95, 0.7, 0.1> }
  finish { Shiny }
}

// Back row: cylinder, disc (with a hole), hexagonal polygon.
cylinder {
  <-3, 0, 3.5>, <-3, 1.6, 3.5>, 0.8
  pigment { color rgb <0.2, 0.7, 0.3> }
  finish { Shiny }
}
disc {
  <0, 1.3, 3.5>, <0, 0.5, -1>, 1.2, 0.45
  pigment { color rgb <0.65, 0.3, 0.8> }
}
polygon {
  7,
  <1, 0>, <0.5, 0.866>, <-0.5, 0.866>, <-1, 0>, <-0.5, -0.866>, <0.5, -0.866>, <1, 0>
  scale 1.1
  rotate <-20, -15, 0>
  translate <3, 1.3, 3.5>
  pigment { color rgb <0.1, 0.75, 0.75> }
}
