// substr() past the end of the string.
#declare S = substr("abc", 3, 2);
