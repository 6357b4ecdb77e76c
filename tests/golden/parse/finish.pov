// finish: every item, floats and colours, declared finishes modified.
#declare Glossy = finish { phong 0.8 phong_size 80 specular 0.2 roughness 0.01 }
sphere { 0, 1 finish { ambient 0.2 diffuse 0.7 brilliance 2 } }
sphere { 0, 1 finish { ambient rgb <0.1, 0.2, 0.3> reflection 0.25 } }
sphere { 0, 1 finish { reflection color rgb <0.5, 0.6, 0.7> } }
sphere { 0, 1 finish { Glossy } }
sphere { 0, 1 finish { Glossy phong 0 } }
sphere { 0, 1 pigment { rgb 1 } finish { Glossy } finish { diffuse 0.4 } }
