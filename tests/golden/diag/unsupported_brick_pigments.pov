// A brick of pigments (POV-Ray's pigment list) is not ours: brick takes two colours.
sphere { 0, 1 pigment { brick pigment { rgb 1 } pigment { rgb 0 } } }
