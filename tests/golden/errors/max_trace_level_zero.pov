// max_trace_level below 1.
global_settings { max_trace_level 0 }
