// Macro calls count with the #if and the expressions around them: 500 calls deep is past the limit.
#macro M(N) #if (N > 0) ((((((((((M(N - 1))))))))))) #else 1 #end #end
#declare X = M(500);
