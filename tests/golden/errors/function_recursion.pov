// A function that calls itself: POV-Ray's functions are not recursive.
#declare F = function(a) { select(a, 0, F(a - 1) + 1) }
