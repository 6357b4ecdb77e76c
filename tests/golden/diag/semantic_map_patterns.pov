// The map patterns' mistakes: a colour map with no entry (POV-Ray: "Must
// have at least one color in color map"), a map entry with three colours,
// agate_turb on another pattern, a noise generator POV-Ray does not have, a
// gradient without a direction, a map or turbulence on checker (not
// supported by asos), and a declared value that is not a colour map.
#declare NotAMap = 1;
sphere { 0, 1 pigment { gradient x color_map { } } }
sphere { 0, 1 pigment { gradient x color_map { [0 rgb 1 rgb 0 rgb 1] } } }
sphere { 0, 1 pigment { marble agate_turb 0.5 } }
sphere { 0, 1 pigment { bozo noise_generator 4 } }
sphere { 0, 1 pigment { gradient 0 } }
sphere { 0, 1 pigment { checker turbulence 0.5 } }
sphere { 0, 1 pigment { brick color_map { [0 rgb 1] } } }
sphere { 0, 1 pigment { wood color_map { NotAMap } } }
