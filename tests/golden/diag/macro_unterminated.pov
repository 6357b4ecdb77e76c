// A #macro without its #end.
#macro Open(A)
  sphere { 0, A }
#if (1) #end
