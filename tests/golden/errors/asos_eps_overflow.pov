// The asos block's eps that overflows.
global_settings { asos { eps 1e308 * 10 } }
