// No #version and no assumed_gamma: POV-Ray 3.7 reads the scene as 3.62 and
// turns gamma correction off, so its colours go to the file as they are.
camera { location <0, 0, -3> look_at 0 }
light_source { <0, 5, -5> rgb 1 }
sphere { 0, 1 pigment { rgb <1, 0.5, 0.2> } }
