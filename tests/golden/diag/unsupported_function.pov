#declare R = rand(seed(42));
