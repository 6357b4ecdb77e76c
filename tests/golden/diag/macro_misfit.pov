// A macro's body is read as entries of where it is called: transforms do not
// fit at the top of a scene.
#macro Lift(H) translate H * y #end
sphere { 0, 1 Lift(2) }
Lift(1)
