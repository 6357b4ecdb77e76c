// A negative max_trace_level.
global_settings { max_trace_level -5 }
