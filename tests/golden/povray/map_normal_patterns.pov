// The normal patterns as pigment patterns (bumps, dents, wrinkles,
// ripples, waves) through colour maps, against POV-Ray's values: five
// flat panels, one each; ripples and waves with a frequency and a phase.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> look_at 0 right 5 * x up 2.8125 * y }
light_source { <0, 0, -100>, rgb 1 }
#declare Map = color_map { [0 rgb <0, 0, 0.3>] [0.3 rgb <1, 0.5, 0>] [0.6 rgb <0.2, 1, 0.2>] [1 rgb 1] }
#declare F = finish { ambient 1 diffuse 0 }
box { <-2.5, 0, 0>, <-1.5, 1.4, 1> pigment { bumps color_map { Map } scale 0.2 } finish { F } }
box { <-1.5, 0, 0>, <-0.5, 1.4, 1> pigment { dents color_map { Map } scale 0.2 } finish { F } }
box { <-0.5, 0, 0>, <0.5, 1.4, 1> pigment { wrinkles color_map { Map } scale 0.3 } finish { F } }
box { <0.5, 0, 0>, <1.5, 1.4, 1> pigment { ripples color_map { Map } scale 0.1 } finish { F } }
box { <1.5, 0, 0>, <2.5, 1.4, 1> pigment { waves color_map { Map } scale 0.1 } finish { F } }
box { <-2.5, -1.4, 0>, <-0.5, 0, 1> pigment { ripples frequency 2 phase 0.3 color_map { Map } scale 0.2 } finish { F } }
box { <-0.5, -1.4, 0>, <1.5, 0, 1> pigment { waves frequency 1.5 phase 0.2 color_map { Map } scale 0.2 } finish { F } }
box { <1.5, -1.4, 0>, <2.5, 0, 1> pigment { wrinkles turbulence 0.3 color_map { Map } scale 0.3 } finish { F } }
