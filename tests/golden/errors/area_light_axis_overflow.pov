// An area light axis that overflows.
light_source { 0, 1 area_light 1e308 * 10 * x, y, 2, 2 }
