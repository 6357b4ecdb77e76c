// Calling macros wrongly.
#macro Two(A, B) sphere { A, B } #end
Two(1)
Two(0, 1, 2)
Two(Undeclared, 1)
#declare R = 1;
R(2)
#declare S = Two;
#macro R() #end
