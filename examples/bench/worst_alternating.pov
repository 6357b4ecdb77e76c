// Worst case "alternating" (docs/performance.md, "Worst cases"): sample
// points that fall alternately in and out of objects at every level, where a
// sampling method's error does not fall as it adds samples. At 120 x 90 one
// unit is one pixel (an orthographic camera):
//   * left, 2 x 2 pixels of the paper's pathological pixel ("Upper Bound on
//     Number of Subdivisions"): in each, tiny spheres (0.004 pixel across) at
//     the centres of its 1, 16 and 256 squares of levels 0, 2 and 4, so a
//     ray through the centre of a square of an even level hits and one of an
//     odd level misses; the true coverage is 0.34 % (273 spheres);
//   * right, a comb of bars 1/32 pixel wide every 1/16 pixel (the squares of
//     MAX 4), 30 pixels square, turned 2 degrees: half covered, the samples of
//     a regular lattice drifting in and out of the bars across it (moire).
// ASOS must stop at MAX (4^MAX leaves at most) and never stall.
//   asos render examples/bench/worst_alternating.pov -W 120 -H 90 -o alternating.png
//   asos-bench accuracy examples/bench/worst_alternating.pov -W 120 -H 90 -o build/worst
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb 0 }
camera { orthographic location <60, 45, -10> look_at <60, 45, 0> right 120 * x up 90 * y }
#declare Flat = texture { pigment { color rgb 1 } finish { ambient 1 diffuse 0 } }

// The pathological pixels: columns 20 and 21, rows 44 and 45 (x from 20, y from 44).
#for (PX, 20, 21)
  #for (PY, 44, 45)
    #for (L, 0, 4, 2)
      #declare N = pow(2, L);
      #for (I, 0, N - 1)
        #for (J, 0, N - 1)
          sphere { <PX + (I + 0.5) / N, PY + (J + 0.5) / N, 0>, 0.002 texture { Flat } }
        #end
      #end
    #end
  #end
#end

// The comb: 30 pixels square about (75, 45).
union {
  #for (K, 0, 30 * 16 - 1)
    box { <K / 16, 0, 0>, <K / 16 + 1 / 32, 30, 0.1> }
  #end
  texture { Flat }
  translate <-15, -15, 0> rotate 2 * z translate <75, 45, 0>
}
