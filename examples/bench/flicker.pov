// Benchmark scene "flicker" (docs/performance.md, "Flicker"): two objects
// smaller than a pixel moving slowly across the image over an animation, as
// `asos-bench stability` renders it (48 frames, `clock` 0 to 1):
//   * a wire 0.3 pixel wide, nearly upright (its slope moves it through
//     every sub-pixel phase along its length), in the top half, moving
//     6 pixels to the right;
//   * a sphere 0.5 pixel across in the bottom half, moving 6 pixels to the
//     right and 1.5 down.
// Sizes are in pixels at any image size: the orthographic view is 4 x 3
// units, so one pixel is 4 / image_width. Both are white and lit by ambient
// only over a black background, so that an image's sum over each half is
// the object's area in pixels: the same in every frame (0.3 times the
// wire's length; pi / 16 for the sphere). A method whose sums change from
// frame to frame flickers.
//   asos render examples/bench/flicker.pov -W 160 -H 120 --frames 1-48 -o flicker_##.png
//   asos-bench stability -o build/stability
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb 0 }
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x * 4 up y * 3 }
#declare Pixel = 4 / image_width;
#declare Shift = 6 * Pixel * clock;
#declare White = texture { pigment { color rgb 1 } finish { ambient 1 diffuse 0 } }

// The wire: from y = 0.3 to 1.2, leaning 1 pixel in 10, from x = -1.
cylinder { <-1 + Shift, 0.3, 0>, <-1 + Shift + 0.09, 1.2, 0>, 0.15 * Pixel texture { White } }
// The sphere: from (0.3, -0.7), down a quarter of its way right.
sphere { <0.3 + Shift, -0.7 - Shift / 4, 0>, 0.25 * Pixel texture { White } }
