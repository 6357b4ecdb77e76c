#declare V = <1, 2, 3>;
#declare W = V.w;
