// assumed_gamma that overflows.
global_settings { assumed_gamma 1e308 * 10 }
