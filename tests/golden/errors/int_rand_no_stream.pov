// rand() of a generator that seed() did not make.
#declare X = rand(3);
