// A transform of a union that overflows its children.
union { sphere { 0, 1 translate 1e308*y } sphere { 0, 1 } translate 1e308*y }
