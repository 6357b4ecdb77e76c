// Cross-check of POV-Ray's reflection { } block and metallic: a gold sphere
// (metallic highlights, reflection from 0.2 head-on to 0.9 at grazing
// angles by falloff 2, tinted by reflection's metallic), a glass sphere of
// ior 1.5 with a Fresnel reflection and conserve_energy, a green sphere with
// a reflection exponent, and a Fresnel reflection without an interior (ior
// 1: only the head-on colour). Rendered by tests/unit/render_golden_test.cpp
// with one ray per pixel; POV-Ray's reference by scripts/update-goldens.sh
// (povray -A).
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 8 }
camera { location <0, 2, -6> look_at <0, 0.6, 0> angle 60 }
light_source { <4, 6, -5> color rgb 1 }
plane { y, 0 pigment { checker rgb <0.9, 0.2, 0.2> rgb <0.9, 0.9, 0.8> } }
sphere { <-1.6, 1, 0>, 1 pigment { rgb <0.8, 0.6, 0.2> }
  finish { diffuse 0.3 specular 0.8 roughness 0.02 metallic reflection { 0.2, 0.9 falloff 2 metallic } } }
sphere { <0.6, 1, 0.5>, 1 pigment { rgbf <0.2, 0.3, 0.8, 0.6> }
  finish { phong 0.7 metallic 0.6 reflection { 0.8 fresnel } conserve_energy } interior { ior 1.5 } }
sphere { <2.1, 0.6, -1>, 0.6 pigment { rgb <0.3, 0.8, 0.3> }
  finish { reflection { 0.1 0.6 exponent 0.6 } } }
sphere { <-0.3, 0.4, -1.6>, 0.4 pigment { rgb <0.9, 0.9, 0.2> }
  finish { reflection { 0.3, 0.8 fresnel on } reflection_exponent 2 } }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.6, 0.7, 1>] [1 rgb <0.1, 0.2, 0.6>] } } }
