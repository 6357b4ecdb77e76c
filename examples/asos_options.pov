// The asos extension: `asos { eps E  max M  jitter on|off }` tunes the
// adaptive supersampling in object space (Genetti & Gordon 1993): eps is the
// colour difference that makes a pyramid subdivide, max the deepest
// subdivision, jitter whether samples are jittered. Set it for the whole
// scene in global_settings, for one object, or for one light (its shadow
// beams); unset fields follow docs/manual/asos.md, "Which setting wins".
// POV-Ray does not know this block: this scene is for asos only.
//
// With asos:     asos render examples/asos_options.pov -o asos_options.png

#version 3.7;

global_settings {
  assumed_gamma 1.0
  asos { eps 0.02 max 4 jitter on }
}
background { color rgb <0.5, 0.6, 0.8> }

camera {
  location <0, 3, -8>
  look_at <0, 1, 0>
  angle 50
}

light_source {
  <-5, 8, -5>, color rgb 1
  area_light <1, 0, 0>, <0, 0, 1>, 4, 4
  asos { eps 0.05 }  // shadow beams may be coarser
}

plane { y, 0 pigment { checker color rgb 0.9, color rgb 0.2 } }

// Fine detail: a smaller eps and deeper subdivision on this sphere only.
sphere {
  <-1.5, 1, 0>, 1
  pigment { checker color rgb <1, 0.8, 0.2>, color rgb <0.6, 0.1, 0.1> scale 0.25 }
  asos { eps 0.005 max 6 }
}

// A plain surface needs little: no jitter, shallow subdivision.
box {
  <0.5, 0, -1>, <2.5, 2, 1>
  pigment { color rgb <0.3, 0.5, 0.9> }
  asos { max 2 jitter off }
}
