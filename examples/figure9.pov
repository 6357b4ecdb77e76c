// An animation after the paper's Figure 9 (Genetti & Gordon 1993, a frame of
// "Shadow of a Doubt", 720 x 486, ASOS with MAX 2 and random 2-pyrays): a
// lamp with a round shade swings on its cord above a table, and the soft
// shadows of the pieces on it sweep across the table and the floor. The
// light is spherical (a circular area light facing each point it lights); the
// clock runs the swing through one period, so frame 48 of 1-48 with
// --clock-to 47/48 leads back to frame 1 and the frames loop.
//   asos render examples/figure9.pov --frames 1-48 --clock-to 0.979167 -W 720 -H 486 -o figure9_##.png
//   asos render examples/figure9.pov --clock 0.125 -W 720 -H 486 -o figure9.png    (one frame)
// global_settings' asos block is the paper's setting: MAX 2, jittered MAX-rays
// (POV-Ray does not know it; without it, POV-Ray 3.7 renders the scene too).

#version 3.7;
global_settings { assumed_gamma 1.0  asos { max 2  jitter on } }

#declare Swing = 35 * sin(2 * pi * clock);          // the cord's angle from the vertical, degrees
#declare Pivot = <0, 4.2, 0.3>;
#declare Bulb = Pivot + vrotate(<0, -2.0, 0>, <Swing * 0.3, 0, Swing>);

camera { location <0, 3.4, -6.2> look_at <0, 0.9, 0.3> right x * 720 / 486 angle 52 }

light_source {
  Bulb, rgb <1.5, 1.4, 1.25>
  area_light <0.35, 0, 0>, <0, 0, 0.35>, 5, 5 circular orient
}
light_source { <-6, 8, -9>, rgb 0.15 shadowless }   // a little fill, so the shadows are not black

// The lamp: its bulb and cord cast no shadow of their own.
sphere { Bulb, 0.12 no_shadow pigment { rgb <1, 0.95, 0.8> } finish { ambient 1 diffuse 0 } }
cylinder { Pivot, Bulb, 0.012 no_shadow pigment { rgb 0.1 } }

plane { y, 0 pigment { checker rgb 0.75, rgb 0.55 scale 0.8 } }
plane { z, 4 pigment { rgb <0.7, 0.68, 0.6> } }

// The table and its legs.
#declare Wood = texture { pigment { rgb <0.45, 0.28, 0.14> } finish { phong 0.3 } }
box { <-1.6, 0.9, -0.8>, <1.6, 1.0, 1.4> texture { Wood } }
#for (I, 0, 3)
  cylinder { <-1.45 + 2.9 * mod(I, 2), 0, -0.65 + 1.9 * div(I, 2)>, <-1.45 + 2.9 * mod(I, 2), 0.9, -0.65 + 1.9 * div(I, 2)>, 0.06
    texture { Wood } }
#end

// The pieces on it.
#declare Piece = pigment { rgb <0.85, 0.2, 0.15> }
sphere { <-0.8, 1.3, 0.2>, 0.3 pigment { Piece } finish { phong 0.6 } }
cone { <0.1, 1.0, 0.6>, 0.3, <0.1, 1.7, 0.6>, 0 pigment { rgb <0.2, 0.4, 0.8> } }
cylinder { <0.9, 1.0, -0.1>, <0.9, 1.5, -0.1>, 0.18 pigment { rgb <0.9, 0.8, 0.3> } }
box { <-0.3, 1.0, -0.5>, <0.2, 1.25, -0.2> rotate y * 20 pigment { rgb 0.9 } }
disc { <1.0, 1.001, 0.9>, y, 0.25 pigment { rgb <0.2, 0.6, 0.3> } }
