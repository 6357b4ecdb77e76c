// A quadric needs a term in x, y or z.
#version 3.7;
quadric { <0, 0, 0>, <0, 0, 0>, <0, 0, 0>, 1 }
