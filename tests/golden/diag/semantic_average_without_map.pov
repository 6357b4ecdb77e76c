// average needs a pigment_map to average.
sphere { 0, 1 pigment { average turbulence 0.2 } }
