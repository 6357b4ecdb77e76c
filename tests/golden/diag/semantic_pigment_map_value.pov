// Outside average, every pigment map entry starts with its value.
#declare Spots = pigment { bozo }
sphere { 0, 1 pigment { gradient y pigment_map { [0 rgb 0] [Spots] } } }
