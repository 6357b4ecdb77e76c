// ambient_light that overflows.
global_settings { ambient_light 1e308 * 10 }
