// sky_sphere and fog against POV-Ray (tests/unit/render_golden_test.cpp):
// a gradient sky with a partly transparent layer over it, turned, over a
// background it lets through; a ground fog and a constant fog with a
// transmit and turbulence; reflections that see both.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -5> look_at <0, 1.2, 0> angle 60 }
light_source { <5, 10, -10>, rgb 1 }
background { rgb <0.2, 0.1, 0.1> }
sky_sphere {
  pigment { gradient y color_map { [0 rgb <1, 0.9, 0.7>] [0.1 rgb <0.3, 0.5, 1>] [1 rgb <0, 0.1, 0.5>] } }
  pigment { bozo scale 0.2 color_map { [0.5 rgbt <1, 1, 1, 1>] [0.7 rgbt <1, 1, 1, 0.3>] } }
  rotate 5 * z
}
fog { fog_type 2 distance 4 color rgb <0.8, 0.8, 0.9> fog_offset 0.2 fog_alt 0.5 }
fog { distance 40 color rgbt <0.9, 0.7, 0.6, 0.6> turbulence 0.5 turb_depth 0.3 }
plane { y, 0 pigment { checker rgb 1, rgb <0.2, 0.3, 0.2> } finish { reflection 0.3 } }
sphere { <0, 1, 0>, 1 pigment { rgb <1, 0.3, 0.2> } finish { phong 0.5 reflection 0.4 } }
