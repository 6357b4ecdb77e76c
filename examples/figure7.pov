// After the paper's Figure 7 (Genetti & Gordon 1993, "Results"): a house of
// a few thousand polygons (the paper's had 2,770) under a spherical light, a
// sun of radius 2 at 40 units: its soft shadows fall from the eaves, the
// shutters, the chimney and the fence. Every board, shingle, slat, brick and
// picket is its own polygon, made by the loops below: 2,340 of them
// (`asos parse examples/figure7.pov | grep -c polygon`). Render:
//   asos render examples/figure7.pov -W 640 -H 480 -o figure7.png --stats
//   asos render examples/figure7.pov -W 640 -H 480 -o figure7.png --aov samples=figure7-samples.png
// POV-Ray 3.7 renders the same file (povray +Iexamples/figure7.pov +W640 +H480 +A0.3).
#version 3.7;

global_settings { assumed_gamma 1.0 ambient_light 1 }
background { color rgb <0.55, 0.7, 0.92> }
camera { location <-9, 4.2, -13> look_at <0.4, 2.3, 0> angle 50 }

// The sun: a spherical light (a circular area light turned toward each point).
light_source {
  <-14, 30, -22>, color rgb 1.35
  area_light <4, 0, 0>, <0, 0, 4>, 9, 9 circular orient
}
// Sky light: a dim, shadowless fill from the other side.
light_source { <20, 15, -5>, color rgb 0.18 shadowless }

#declare Matte = finish { ambient 0.1 diffuse 0.75 }
#declare Siding  = texture { pigment { color rgb <0.93, 0.9, 0.82> } finish { Matte } }
#declare Trim    = texture { pigment { color rgb 0.97 } finish { ambient 0.1 diffuse 0.8 } }
#declare Shutter = texture { pigment { color rgb <0.16, 0.3, 0.22> } finish { Matte } }
#declare Glass   = texture { pigment { color rgb <0.08, 0.1, 0.14> } finish { ambient 0.1 diffuse 0.2 phong 0.8 } }
#declare Door    = texture { pigment { color rgb <0.5, 0.12, 0.1> } finish { Matte phong 0.3 } }
#declare Brick   = texture { pigment { color rgb <0.58, 0.24, 0.16> } finish { Matte } }
#declare Mortar  = texture { pigment { color rgb 0.62 } finish { Matte } }
#declare Stone   = texture { pigment { color rgb <0.6, 0.58, 0.55> } finish { Matte } }

// A four-sided polygon (the points in order, closed by repeating the first).
#macro Quad(A, B, C, D, T)
  polygon { 5, A, B, C, D, A texture { T } }
#end

// The lawn.
plane { y, 0 pigment { color rgb <0.3, 0.5, 0.2> } finish { Matte } }

// The house: 8 wide (x), 6 deep (z), walls 3 high, the ridge at 5 along x.
#declare W = 4;       // half width
#declare D = 3;       // half depth
#declare H = 3;       // wall height
#declare R = 5;       // ridge height
#declare Board = 0.15;

// Clapboard siding: boards 0.15 high, each tilted out 2 cm at its foot.
#for (Y, 0, H - Board / 2, Board)
  Quad(<-W, Y, -D - 0.02>, <W, Y, -D - 0.02>, <W, Y + Board, -D>, <-W, Y + Board, -D>, Siding)  // front
  Quad(<-W, Y, D + 0.02>, <W, Y, D + 0.02>, <W, Y + Board, D>, <-W, Y + Board, D>, Siding)      // back
#end
// The gable ends (x = -W and x = W): boards up the walls and into the gables,
// each board of the gable cut to the roof's slope.
#for (Y, 0, R - Board / 2, Board)
  #declare Y1 = min(Y + Board, R);
  #declare Z0 = (Y < H ? D : D * (R - Y) / (R - H));     // half width at the board's foot
  #declare Z1 = (Y1 <= H ? D : D * (R - Y1) / (R - H));  // and at its top
  #for (S, -1, 1, 2)
    Quad(<S * (W + 0.02), Y, -Z0>, <S * (W + 0.02), Y, Z0>, <S * W, Y1, Z1>, <S * W, Y1, -Z1>, Siding)
  #end
#end

// Corner boards and the trim under the eaves.
#for (S, -1, 1, 2)
  Quad(<S * W - 0.12, 0, -D - 0.04>, <S * W + 0.12, 0, -D - 0.04>,
       <S * W + 0.12, H, -D - 0.04>, <S * W - 0.12, H, -D - 0.04>, Trim)
  Quad(<S * (W + 0.04), 0, -D - 0.12>, <S * (W + 0.04), 0, -D + 0.12>,
       <S * (W + 0.04), H, -D + 0.12>, <S * (W + 0.04), H, -D - 0.12>, Trim)
#end
Quad(<-W, H - 0.2, -D - 0.05>, <W, H - 0.2, -D - 0.05>, <W, H, -D - 0.05>, <-W, H, -D - 0.05>, Trim)

// The roof: two planes from the eaves (0.4 beyond the walls) to the ridge,
// shingled in staggered rows; each shingle's butt lifted 2 cm off the roof.
#declare Over = 0.4;
#declare Eave = <0, H - Over * (R - H) / D, D + Over>;   // the eave line at the back, y and z
#declare Ridge = <0, R, 0>;
#declare Up = Ridge - Eave;                               // up the slope, back plane
#declare Slope = vlength(Up);
#declare Rows = 26;
#declare Row = Slope / Rows;
#declare Across = 32;
#declare Shingle = (2 * (W + Over)) / Across;
#declare Random = seed(1993);
#for (S, -1, 1, 2)                                       // S = -1: the front plane
  #declare U = <0, Up.y, S * Up.z> / Slope;               // unit, up the slope
  #declare N = vnormalize(vcross(U, x));
  #declare N = (N.y < 0 ? -N : N);                        // out of the roof
  #declare E = <0, Eave.y, S * Eave.z>;
  // the roof deck under the shingles
  Quad(E - (W + Over) * x, E + (W + Over) * x, Ridge + (W + Over) * x, Ridge - (W + Over) * x, Mortar)
  #for (I, 0, Rows - 1)
    #declare Shift = mod(I, 2) * Shingle / 2;
    #for (J, 0, Across - (mod(I, 2) = 1 ? 2 : 1))
      #declare X0 = -W - Over + J * Shingle + Shift;
      #declare V0 = E + U * I * Row + N * 0.022;
      #declare V1 = E + U * min((I + 1.4) * Row, Slope) + N * 0.002;
      #declare Grey = 0.22 + 0.1 * rand(Random);
      Quad(V0 + (X0 + 0.01) * x, V0 + (X0 + Shingle - 0.01) * x,
           V1 + (X0 + Shingle - 0.01) * x, V1 + (X0 + 0.01) * x,
           texture { pigment { color rgb <Grey * 1.1, Grey, Grey * 0.95> } finish { Matte } })
    #end
  #end
#end
// The ridge cap.
Quad(<-W - Over, R + 0.03, -0.15>, <W + Over, R + 0.03, -0.15>, <W + Over, R + 0.06, 0>, <-W - Over, R + 0.06, 0>, Trim)
Quad(<-W - Over, R + 0.06, 0>, <W + Over, R + 0.06, 0>, <W + Over, R + 0.03, 0.15>, <-W - Over, R + 0.03, 0.15>, Trim)

// A window on a wall: its centre C, the wall's outward normal Out and the
// wall's horizontal direction Side; a frame, six panes between muntins, and
// two louvred shutters of twelve slats each.
#macro Window(C, Out, Side)
  #local Wd = 0.55; #local Ht = 0.75;   // half width and half height
  #local Up = y;
  #local F = C + Out * 0.05;
  #local P = C + Out * 0.03;
  Quad(P - Side * Wd - Up * Ht, P + Side * Wd - Up * Ht, P + Side * Wd + Up * Ht, P - Side * Wd + Up * Ht, Glass)
  // the frame
  Quad(F - Side * (Wd + 0.1) - Up * (Ht + 0.12), F + Side * (Wd + 0.1) - Up * (Ht + 0.12),
       F + Side * (Wd + 0.1) - Up * Ht, F - Side * (Wd + 0.1) - Up * Ht, Trim)
  Quad(F - Side * (Wd + 0.1) + Up * Ht, F + Side * (Wd + 0.1) + Up * Ht,
       F + Side * (Wd + 0.1) + Up * (Ht + 0.1), F - Side * (Wd + 0.1) + Up * (Ht + 0.1), Trim)
  Quad(F - Side * (Wd + 0.1) - Up * Ht, F - Side * Wd - Up * Ht, F - Side * Wd + Up * Ht, F - Side * (Wd + 0.1) + Up * Ht, Trim)
  Quad(F + Side * Wd - Up * Ht, F + Side * (Wd + 0.1) - Up * Ht, F + Side * (Wd + 0.1) + Up * Ht, F + Side * Wd + Up * Ht, Trim)
  // the sill, sticking out
  Quad(F - Side * (Wd + 0.15) - Up * (Ht + 0.12), F + Side * (Wd + 0.15) - Up * (Ht + 0.12),
       F + Side * (Wd + 0.15) - Up * (Ht + 0.12) + Out * 0.12, F - Side * (Wd + 0.15) - Up * (Ht + 0.12) + Out * 0.12, Trim)
  // the muntins: one upright, two across
  #local M = C + Out * 0.04;
  Quad(M - Side * 0.02 - Up * Ht, M + Side * 0.02 - Up * Ht, M + Side * 0.02 + Up * Ht, M - Side * 0.02 + Up * Ht, Trim)
  #for (K, -1, 1, 2)
    #local Yk = K * Ht / 3;
    Quad(M - Side * Wd + Up * (Yk - 0.02), M + Side * Wd + Up * (Yk - 0.02),
         M + Side * Wd + Up * (Yk + 0.02), M - Side * Wd + Up * (Yk + 0.02), Trim)
  #end
  // the shutters, open against the wall on both sides
  #for (K, -1, 1, 2)
    #local S0 = C + Out * 0.04 + Side * K * (Wd + 0.12);
    #local S1 = S0 + Side * K * 0.55;
    Quad(S0 - Up * Ht, S1 - Up * Ht, S1 - Up * (Ht - 0.06), S0 - Up * (Ht - 0.06), Shutter)
    Quad(S0 + Up * (Ht - 0.06), S1 + Up * (Ht - 0.06), S1 + Up * Ht, S0 + Up * Ht, Shutter)
    #for (L, 0, 11)
      #local Yl = -Ht + 0.06 + (L + 0.5) * (2 * Ht - 0.12) / 12;
      Quad(S0 + Up * (Yl - 0.06) + Out * 0.04, S1 + Up * (Yl - 0.06) + Out * 0.04,
           S1 + Up * (Yl + 0.05), S0 + Up * (Yl + 0.05), Shutter)
    #end
  #end
#end

// Two windows on the front, beside the door, and one on the gable end we see.
Window(<-2.2, 1.45, -D - 0.02>, -z, x)
Window(<2.2, 1.45, -D - 0.02>, -z, x)
Window(<-W - 0.02, 1.45, -1.6>, -x, z)

// The front door: six raised panels in a frame, and three stone steps.
#declare DoorC = <0, 1.05, -D - 0.04>;
Quad(DoorC + <-0.55, -1.05, -0.01>, DoorC + <0.55, -1.05, -0.01>, DoorC + <0.55, 1.15, -0.01>, DoorC + <-0.55, 1.15, -0.01>, Trim)
Quad(DoorC + <-0.45, -1.05, -0.02>, DoorC + <0.45, -1.05, -0.02>, DoorC + <0.45, 1.05, -0.02>, DoorC + <-0.45, 1.05, -0.02>, Door)
#for (I, 0, 2)
  #for (J, -1, 1, 2)
    #declare Pc = DoorC + <J * 0.2, -0.7 + I * 0.68, -0.03>;
    Quad(Pc + <-0.14, -0.26, 0>, Pc + <0.14, -0.26, 0>, Pc + <0.14, 0.26, 0>, Pc + <-0.14, 0.26, 0>, Door)
  #end
#end
#for (I, 0, 2)
  #declare T = 0.18 * (3 - I);        // the top of step I
  #declare Z = -D - 0.3 * (3 - I);     // its front
  Quad(<-0.8, T, Z>, <0.8, T, Z>, <0.8, T, Z + 0.3>, <-0.8, T, Z + 0.3>, Stone)            // tread
  Quad(<-0.8, T - 0.18, Z>, <0.8, T - 0.18, Z>, <0.8, T, Z>, <-0.8, T, Z>, Stone)          // riser
  Quad(<-0.8, T - 0.18, Z>, <-0.8, T, Z>, <-0.8, T, -D>, <-0.8, T - 0.18, -D>, Stone)      // side
#end

// The chimney, of bricks, on the gable end we see: a stack 0.9 x 0.6 up past the roof.
#declare Cx = -W - 0.35;
#declare Cz = 1.3;
#for (Y, 0, 6.2, 0.16)
  #declare Off = mod(floor(Y / 0.16 + 0.5), 2) * 0.15;
  #for (K, -0.3 + Off - 0.3, 0.3, 0.3)                            // the face toward -x
    #declare K0 = max(K, -0.3); #declare K1 = min(K + 0.29, 0.3);
    #if (K1 > K0)
      Quad(<Cx - 0.3, Y, Cz + K0>, <Cx - 0.3, Y, Cz + K1>, <Cx - 0.3, Y + 0.15, Cz + K1>, <Cx - 0.3, Y + 0.15, Cz + K0>, Brick)
    #end
  #end
  #for (K, -0.3 + Off - 0.3, 0.3, 0.3)                            // the face toward -z
    #declare K0 = max(K, -0.3); #declare K1 = min(K + 0.29, 0.3);
    #if (K1 > K0)
      Quad(<Cx + K0, Y, Cz - 0.3>, <Cx + K1, Y, Cz - 0.3>, <Cx + K1, Y + 0.15, Cz - 0.3>, <Cx + K0, Y + 0.15, Cz - 0.3>, Brick)
    #end
  #end
  // the mortar behind the bricks
  Quad(<Cx - 0.299, Y, Cz - 0.3>, <Cx - 0.299, Y, Cz + 0.3>, <Cx - 0.299, Y + 0.16, Cz + 0.3>, <Cx - 0.299, Y + 0.16, Cz - 0.3>, Mortar)
  Quad(<Cx - 0.3, Y, Cz - 0.299>, <Cx + 0.3, Y, Cz - 0.299>, <Cx + 0.3, Y + 0.16, Cz - 0.299>, <Cx - 0.3, Y + 0.16, Cz - 0.299>, Mortar)
#end
Quad(<Cx - 0.34, 6.36, Cz - 0.34>, <Cx + 0.34, 6.36, Cz - 0.34>, <Cx + 0.34, 6.36, Cz + 0.34>, <Cx - 0.34, 6.36, Cz + 0.34>, Mortar)

// A picket fence along the front, with a gap at the path.
#for (X, -8, 8, 0.28)
  #if (abs(X) > 0.9)
    Quad(<X - 0.05, 0, -7>, <X + 0.05, 0, -7>, <X + 0.05, 0.9, -7>, <X - 0.05, 0.9, -7>, Trim)
    polygon { 4, <X - 0.05, 0.9, -7>, <X + 0.05, 0.9, -7>, <X, 1.0, -7>, <X - 0.05, 0.9, -7> texture { Trim } }
    Quad(<X + 0.05, 0, -7>, <X + 0.05, 0, -6.96>, <X + 0.05, 0.9, -6.96>, <X + 0.05, 0.9, -7>, Trim)
  #end
#end
#for (Y, 0.25, 0.7, 0.45)
  #for (S, -1, 1, 2)
    Quad(<S * 0.95, Y, -6.95>, <S * 8.1, Y, -6.95>, <S * 8.1, Y + 0.07, -6.95>, <S * 0.95, Y + 0.07, -6.95>, Trim)
  #end
#end

// The path to the door: flat stones, a little apart.
#declare Random = seed(7);
#for (I, 0, 12)
  #for (J, -1, 1, 2)
    #declare Zs = -D - 1.05 - I * 0.3;
    #declare Xs = J * 0.3 + (rand(Random) - 0.5) * 0.04;
    Quad(<Xs - 0.27, 0.01, Zs>, <Xs + 0.27, 0.01, Zs>, <Xs + 0.27, 0.01, Zs + 0.26>, <Xs - 0.27, 0.01, Zs + 0.26>, Stone)
  #end
#end
