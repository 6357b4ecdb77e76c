// The asos block's max beyond int.
global_settings { asos { max 1e10 } }
