// point_at belongs to spotlights, cylinder lights and parallel lights.
light_source { <0, 10, 0>, color rgb 1 point_at <0, 0, 0> }
