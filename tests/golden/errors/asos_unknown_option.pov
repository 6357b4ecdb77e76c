// An option the asos block does not have.
global_settings { asos { depth 3 } }
