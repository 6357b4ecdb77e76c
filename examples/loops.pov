// Scene-language features: #declare, #while and #for loops, #if, union with a
// texture inherited by the members that have none, and transforms that move
// an object together with the pigment it already has. POV-Ray 3.7 renders it
// too.
//
// With asos:     asos render examples/loops.pov -o loops.png
// With POV-Ray:  povray +W640 +H480 +A0.1 examples/loops.pov

#version 3.7;

global_settings { assumed_gamma 1.0 }
background { color rgb <0.9, 0.92, 1.0> }

camera {
  location <0, 9, -13>
  look_at <0, 0, 0>
  angle 42
}

light_source { <10, 20, -15>, color rgb 1 }

#declare Rows = 5;
#declare Spacing = 1.6;

// A ring of pillars: one union; the pillars without a pigment take the
// union's, the every-third one keeps its own.
union {
  #for (I, 0, 11)
    cylinder {
      <0, 0, 0>, <0, 1 + mod(I, 4) * 0.4, 0>, 0.3
      #if (mod(I, 3) = 0)
        pigment { color rgb <0.9, 0.3, 0.2> }
      #end
      translate <5, 0, 0>
      rotate <0, I * 30, 0>
    }
  #end
  pigment { color rgb <0.4, 0.4, 0.45> }
}

// A grid of spheres whose size and colour vary with the position.
#declare Row = 0;
#while (Row < Rows)
  #declare Col = 0;
  #while (Col < Rows)
    #declare P = <(Col - (Rows - 1) / 2) * Spacing, 0.5, (Row - (Rows - 1) / 2) * Spacing>;
    sphere {
      P, 0.25 + 0.05 * (Row + Col)
      pigment { color rgb <Col / (Rows - 1), 0.5, Row / (Rows - 1)> }
      finish { phong 0.5 }
    }
    #declare Col = Col + 1;
  #end
  #declare Row = Row + 1;
#end

// The floor's checker is scaled before the plane moves: the checker moves
// with it.
plane {
  y, 0
  pigment { checker color rgb 1, color rgb 0.8 scale 2 }
  translate <1, 0, 1>
}
