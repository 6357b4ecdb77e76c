// concat of many parts past --max-string-length (each part within it).
#declare S = str(1, 250, 0);
#declare T = concat(S, S, S, S, S, S, S, S, S, S);
#declare U = concat(T, T, T, T, T, T, T, T, T, T);
#declare V = concat(U, U, U, U, U, U, U, U, U, U);
#declare W = concat(V, V, V, V, V);
