// A vector has 2 to 5 components.
#declare V = <1, 2, 3, 4, 5, 6>;
