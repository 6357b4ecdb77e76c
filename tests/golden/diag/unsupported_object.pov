// POV-Ray objects asos does not render are named.
sphere { 0, 1 }
isosurface { function { x } }
