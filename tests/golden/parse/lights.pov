// light_source: point, area, linear, spherical; fade, shadowless, area_illumination, asos.
light_source { <10, 10, -10>, color rgb 1 }
light_source { <0, 5, 0> color rgb <1, 0.9, 0.8> shadowless }
light_source {
  <0, 8, 0>, color rgb 0.5
  area_light <2, 0, 0>, <0, 0, 2>, 4, 4
  adaptive 1
  jitter
}
light_source { <5, 5, 5>, rgb 1 area_light x*3, <0, 0, 0>, 6, 1 area_illumination }
light_source { <5, 5, -5>, rgb 1 area_light x*3, z, 6, 3 area_illumination off asos { emitter panel } }
light_source {
  <-5, 5, 5>, 1
  area_light <1, 0, 0>, <0, 1, 0>, 5, 5
  circular
  orient
  fade_distance 4
  fade_power 2
  asos { eps 0.1 jitter off }
  translate y
}
#declare Sun = light_source { <100, 100, -100>, color rgb <1, 1, 0.9> }
light_source { Sun rotate <0, 45, 0> }
