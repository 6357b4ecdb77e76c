// Light sources asos renders: an area light (soft shadows), a linear light
// (an area light with one axis of zero length) and a spherical light
// (`circular orient` with equal axes). POV-Ray 3.7 renders it too.
//
// With asos:     asos render examples/lights.pov -o lights.png
// With POV-Ray:  povray +W640 +H480 +A0.1 examples/lights.pov

#version 3.7;

global_settings { assumed_gamma 1.0 }
background { color rgb 0.05 }

camera {
  location <0, 6, -11>
  look_at <0, 0.8, 0>
  angle 45
}

// A 2 x 2 square area light, 5 x 5 samples.
light_source {
  <-6, 9, -4>, color rgb 0.5
  area_light <2, 0, 0>, <0, 0, 2>, 5, 5
  adaptive 1
  jitter
}

// A linear light: a 4-unit tube along x.
light_source {
  <0, 10, 6>, color rgb <0.35, 0.3, 0.25>
  area_light <4, 0, 0>, <0, 0, 0>, 8, 1
}

// A spherical light of radius 0.75: circular, oriented to face each point.
light_source {
  <6, 7, -6>, color rgb <0.25, 0.3, 0.4>
  area_light <1.5, 0, 0>, <0, 1.5, 0>, 6, 6
  circular
  orient
  fade_distance 12
  fade_power 1
}

plane {
  y, 0
  pigment { color rgb 0.8 }
}

#for (I, -2, 2)
  cylinder {
    <I * 2, 0, 0>, <I * 2, 0.6 + (I + 2) * 0.5, 0>, 0.45
    pigment { color rgb <0.9, 0.55 + I * 0.1, 0.2> }
    finish { specular 0.4 roughness 0.02 }
  }
#end
