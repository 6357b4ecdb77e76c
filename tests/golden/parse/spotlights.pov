// light_source: spotlight and cylinder with POV-Ray's defaults and with their
// own radius, falloff and tightness; parallel; an area spotlight; point_at
// moved by the light's transforms.
light_source { <0, 10, 0>, color rgb 1 spotlight }
light_source { <0, 10, 0>, color rgb 1 spotlight point_at <1, 0, 0> radius 12 falloff 20 tightness 10 }
light_source { <0, 5, 0>, color rgb <0.3, 0.4, 1> cylinder point_at <0, 0, 0> }
light_source { <0, 5, 0>, color rgb 1 cylinder radius 0.3 falloff 0.6 tightness 2 point_at <0, 0, 1> }
light_source { <-8, 3, 1>, color rgb 0.25 parallel point_at <0, 0, 0> }
light_source {
  <0, 8, 0>, color rgb 0.5
  spotlight radius 20 falloff 30 point_at <0, 0, 0>
  area_light <2, 0, 0>, <0, 0, 2>, 4, 4
  translate <1, 0, 0>
  rotate <0, 90, 0>
}
