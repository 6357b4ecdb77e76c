// An area light's lattice size beyond int.
light_source { 0, 1 area_light x, y, 1e10, 2 }
