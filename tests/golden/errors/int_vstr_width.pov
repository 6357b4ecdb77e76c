// vstr() with a width beyond int.
#declare S = vstr(3, <1, 2, 3>, ", ", -1e10, 1);
