// As in POV-Ray, radius, falloff and tightness follow spotlight or cylinder,
// and point_at follows them or parallel.
light_source { <0, 10, 0>, color rgb 1 radius 10 spotlight }
