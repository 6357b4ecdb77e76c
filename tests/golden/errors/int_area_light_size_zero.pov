// An area light's lattice size of 0.
light_source { 0, 1 area_light x, y, 0, 2 }
