// A second texture on one object would be a layered texture.
sphere { 0, 1 pigment { color rgb 1 } texture { pigment { color rgb <1, 0, 0> } } }
