// POV-Ray: "Cannot use pigment_map with this pigment type."
sphere { 0, 1 pigment { rgb <1, 0, 0> pigment_map { [0 rgb 0] [1 rgb 1] } } }
