// Each side of an area light needs at least one light.
light_source { <0, 10, 0>, color rgb 1 area_light <1, 0, 0>, <0, 0, 1>, 0, 4 }
