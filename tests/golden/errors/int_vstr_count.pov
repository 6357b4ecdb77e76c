// vstr() with a component count beyond int.
#declare S = vstr(1e12, <1, 2, 3>, ", ", 0, 1);
