// A macro used as a value without a call.
#macro M() 1 #end
#declare X = M;
