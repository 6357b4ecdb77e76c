// A scene for POV-Ray 3.1 or earlier: POV-Ray 3.7 warns that it does not
// reproduce the defects of those versions.
#version 3.1;
global_settings { assumed_gamma 2.2 }
sphere { 0, 1 pigment { rgb <1, 0.5, 0.2> } }
