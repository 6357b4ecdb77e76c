// The asos block's max below 0.
global_settings { asos { max -1 } }
