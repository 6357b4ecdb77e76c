// A max_trace_level beyond any integer is capped too (POV-Ray's cast would not be defined).
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 1e300 }
sphere { 0, 1 }
