// The asos block's eps of 0.
global_settings { asos { eps 0 } }
