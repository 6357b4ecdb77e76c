// The paper's Figure 8 (Genetti & Gordon 1993, "Results"): an office under an
// area light rendered four ways side by side, to show where ASOS puts its
// rays. The office is examples/bench/room.pov, seen through a 3:2 camera as
// the paper's 1024 x 683 images; the four renders of the figure:
//   asos render examples/figure8.pov -W 1024 -H 683 --max 3 -o figure8_asos.png                  (upper left)
//   asos render examples/figure8.pov -W 1024 -H 683 --max 3 --jitter on -o figure8_random.png    (lower left: random MAX-cones)
//   asos render examples/figure8.pov -W 1024 -H 683 --method jitter --samples 3 -o figure8_3x3.png  (upper right)
//   asos render examples/figure8.pov -W 1024 -H 683 --method jitter --samples 4 -o figure8_4x4.png  (lower right)
// Add --stats to each to compare the rays they trace, as the paper does
// (ASOS traced less than a fourth of the rays of 4x4 sampling there).
#version 3.7;
#include "bench/room.pov"

// room.pov's camera, its image 3:2 instead of 4:3 (the last camera is the one used).
camera { location <2.4, 1.65, -2.8> look_at <-1.0, 0.8, 1.3> angle 70 right x * 1024 / 683 }
