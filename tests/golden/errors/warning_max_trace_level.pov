// Past POV-Ray 3.7's cap of 256: a warning, and 256.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 100000 }
sphere { 0, 1 }
