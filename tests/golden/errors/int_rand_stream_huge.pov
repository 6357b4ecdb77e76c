// rand() of a generator number beyond int.
#declare R = seed(1);
#declare X = rand(1e10);
