// A sphere with a negative radius means nothing.
sphere { <0, 1, 0>, -1 }
