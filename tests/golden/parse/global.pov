// global_settings, background, #version, and the asos extension.
#version 3.6;
global_settings {
  assumed_gamma 2.2
  max_trace_level 10
  ambient_light color rgb <0.5, 0.5, 0.6>
  asos { eps 0.01 max 5 jitter on }
}
background { color rgb <0.1, 0.2, 0.4> }
sphere { 0, 1 asos { eps 0.001 } }
sphere { 0, 1 asos { max 2 jitter off } }
union { sphere { 0, 1 } box { 0, 1 asos { max 7 } } asos { eps 0.5 } }
#version 3.7;
