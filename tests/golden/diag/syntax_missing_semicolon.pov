// #declare of a float needs its semicolon (POV-Ray 3.5 and later).
#declare Radius = 2
sphere { 0, Radius }
