// Arrays: array[N], more dimensions, initialisers, elements read and
// assigned, dimensions and dimension_size, defined() on elements, arrays of
// objects; an index is rounded as POV-Ray does (plus 1e-10, truncated).
#declare Corners = array[2][3] { {0, 1, 2}, {3, 4, 5} };
#declare Radii = array[3];
#declare Radii[0] = 0.5;
#declare Radii[2] = 1.5;
#for (I, 0, dimension_size(Radii, 1) - 1)
  #if (defined(Radii[I]))
    sphere { <Corners[1][I], 0, 0>, Radii[I] }
  #end
#end
#declare Copy = Corners;
#declare Copy[0][0] = 99;                     // Corners keeps its 0
box { Corners[0][0], dimensions(Corners) }
#declare Shapes = array[2] { sphere { 0, 1 }, box { 0, 1 } }
object { Shapes[1] translate Corners[0][1.9999999999] * y }
#macro Fill(A) #declare A[1] = 7; #end        // an array passed by reference
Fill(Radii)
cylinder { 0, y, Radii[1] }
