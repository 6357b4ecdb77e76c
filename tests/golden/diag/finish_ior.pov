sphere { 0, 1 finish { phong 0.5 ior 1.5 } }
