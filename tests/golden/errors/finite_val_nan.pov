// val() of "nan".
#declare X = val("nan");
