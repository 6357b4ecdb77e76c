// A brick of textures in a pigment is not ours: brick takes two colours or two pigments.
sphere { 0, 1 pigment { brick texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } } }
