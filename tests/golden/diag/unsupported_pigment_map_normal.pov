// A pigment map in a normal: POV-Ray's "can only be used in a pigment".
sphere { 0, 1 normal { bozo pigment_map { [0 rgb 0] [1 rgb 1] } } }
