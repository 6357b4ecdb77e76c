// A macro called with too many arguments.
#macro M(A) A #end
#declare X = M(1, 2);
