light_source { <0, 10, 0>, color rgb 1 spotlight point_at 0 looks_like { sphere { 0, 1 } } }
