// A light's colour, ambient, reflection and ambient_light are red, green and
// blue only: POV-Ray ignores filter and transmit there with a warning, and a
// float is a grey (`color 1.5` is rgb 1.5, without a warning). The
// background keeps them: its transmit darkens it, its filter does nothing.
#version 3.7;
global_settings { assumed_gamma 1 ambient_light rgbt <1, 1, 1, 0.5> }
#declare Half = color 0.5;
background { rgbft <0.2, 0.3, 0.4, 0.5, 0.25> }
light_source { <0, 5, -5> color 1.5 }
light_source { <0, 5, -5> rgbf <1, 1, 1, 0.2> }
light_source { <0, 5, -5> Half }
sphere { 0, 1 pigment { rgb 1 } finish { ambient color 0.1 transmit 0.2 reflection rgbft 0.1 } }
