// Directives: #declare/#local/#undef, #if/#elseif/#else, #ifdef/#ifndef,
// #while, #for (with and without a step), #debug/#warning (to stderr).
#declare N = 3;
#local L = 1;
#if (N > 5)
  sphere { 0, 5 }
#elseif (N > 2)
  sphere { 0, N }
#else
  sphere { 0, 1 }
#end
#ifdef (L) box { 0, L } #end
#undef L
#ifndef (L) box { 0, 2 } #end
#declare I = 0;
#while (I < N)
  cylinder { <I, 0, 0>, <I, 1, 0>, 0.1 }
  #declare I = I + 1;
#end
#for (J, 0, 1, 0.5) sphere { <J, 0, 0>, 0.25 } #end
#for (K, 3, 1, -1) disc { <0, K, 0>, y, K } #end
#debug concat("N is ", str(N, 0, 0), "\n")
union {
  #for (K, 1, 2)
    sphere { K * x, 0.5 #if (K = 2) pigment { color rgb <1, 0, 0> } #end }
  #end
}
