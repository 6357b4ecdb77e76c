// A float, a vector or a colour declared from a name or a macro's value needs
// its ';' (POV-Ray 3.5 and later); a string or an object does not.
#declare F = 1;
#declare Text = "abc";
#declare S1 = Text
#declare M = sphere { 0, 1 }
#declare Ball = M
#macro One() 1 #end
#declare G = F
#declare H = One()
sphere { 0, G + H }
