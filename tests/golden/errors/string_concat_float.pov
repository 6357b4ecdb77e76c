// concat() of a float.
#declare S = concat("a", 1);
