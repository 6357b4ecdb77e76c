// A light's emitter is povray or panel.
light_source { <0, 10, 0>, color rgb 1 area_light <1, 0, 0>, <0, 0, 1>, 4, 4 asos { emitter lambert } }
