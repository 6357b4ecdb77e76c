// Transforms that together overflow.
sphere { 0, 1 translate 1e308*x scale 10 }
