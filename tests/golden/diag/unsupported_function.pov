#declare V = vturbulence(2, 0.5, 6, <1, 2, 3>);
