// A macro that calls itself without end: the nesting limit, not the stack, stops it.
#macro Down(N) Down(N + 1) #end
#declare X = Down(0);
