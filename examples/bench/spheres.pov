// A benchmark scene for asos-bench render: 1600 small spheres on a plane, so
// that nearly every pixel holds an outline, the hardest case for ASOS (its
// covered pixels cost one ray; here few pixels are covered). Positions, radii
// and colours come from a fixed sequence, so every run renders the same scene.
//
// Time every method on it:
//   build/asos-bench render examples/bench/spheres.pov --repeat 3
// Render it:
//   build/asos render examples/bench/spheres.pov -o spheres.png

#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.5, 0.6, 0.8> }
camera { location <0, 6, -14> look_at <0, 0, 0> angle 50 }
light_source { <-10, 20, -10>, color rgb 1 }
plane { y, 0 pigment { color rgb 0.8 } }
#declare N = 40;
#for (I, 0, N - 1)
  #for (J, 0, N - 1)
    #declare U = mod(I * 0.618034 + J * 0.754878, 1);
    #declare V = mod(I * 0.569840 + J * 0.414214, 1);
    #declare R = 0.08 + 0.17 * mod(I * 0.381966 + J * 0.267949, 1);
    sphere {
      <-10 + 20 * (I + U) / N, R + 1.5 * mod(I * 0.2 + J * 0.7, 1), -8 + 20 * (J + V) / N>, R
      pigment { color rgb <0.3 + 0.7 * U, 0.3 + 0.7 * V, 0.3 + 0.7 * mod(U + V, 1)> }
    }
  #end
#end
