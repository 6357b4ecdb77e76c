// adaptive beyond int.
light_source { 0, 1 area_light x, y, 2, 2 adaptive 1e10 }
