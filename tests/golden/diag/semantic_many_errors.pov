// Every semantic error of a file is reported, then the run fails.
sphere { 0, -1 }
box { 0, 1 scale 0 }
#declare A = Missing + 1;
sphere { A, 1 }   // A is an error already: not reported again
cylinder { 0, 0, 1 }
light_source { 0, 1 fade_distance -1 }
global_settings { assumed_gamma 0 max_trace_level 0 }
