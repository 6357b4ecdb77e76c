sphere { 0, 1 finish { reflection { 0.1, 0.9 fresnel metallic } falloff 2 } }
