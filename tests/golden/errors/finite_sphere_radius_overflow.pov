// A sphere radius that overflows.
sphere { 0, 1e308 * 2 }
