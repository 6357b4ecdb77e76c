// A texture pattern of brick is not ours: brick goes in the pigment.
sphere { 0, 1 texture { brick texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } } }
