// pigment: colours in every POV-Ray form, checker with given and default
// colours, declared pigments, pattern transforms. Filter and transmit are
// zero: anything else makes the surface transparent (tests/unit/transparency_test.cpp).
#declare Orange = color rgb <1, 0.5, 0>;
#declare Stripes = pigment { checker color rgb 1, color rgb 0 scale <1, 10, 1> }
sphere { 0, 1 pigment { color rgb <1, 0, 0> } }
sphere { 0, 1 pigment { rgb 0.5 } }
sphere { 0, 1 pigment { Orange } }
sphere { 0, 1 pigment { color Orange filter 0 } }
sphere { 0, 1 pigment { colour red 0.2 green 0.4 blue 0.6 transmit 0 } }
sphere { 0, 1 pigment { rgbf <1, 1, 1, 0> } }
sphere { 0, 1 pigment { rgbt <1, 1, 1, 0> } }
sphere { 0, 1 pigment { rgbft <0.1, 0.2, 0.3, 0, 0> } }
sphere { 0, 1 pigment { rgbf <1, 1, 1, 0.5> filter 0 } }  // the last word counts
sphere { 0, 1 pigment { color 0 } }  // a float is all five components
sphere { 0, 1 pigment { checker } }  // POV-Ray's default blue and green
sphere { 0, 1 pigment { checker color rgb <1, 0, 0> } }
sphere { 0, 1 pigment { checker Orange, rgb 0 rotate <0, 0, 45> translate 0.5 } }
sphere { 0, 1 pigment { Stripes } }
sphere { 0, 1 pigment { Stripes scale 2 } }
// As in POV-Ray 3.7 (checked with povray): a whole colour (rgb…, or an
// expression after `color`) opens a colour, components after it override, and
// the next whole colour is the next value, commas or not.
sphere { 0, 1 pigment { checker rgb <1, 0, 0> rgb <0, 0, 1> } }
sphere { 0, 1 pigment { checker rgb <1, 0, 0> green 1 rgb <0, 0, 1> } }
sphere { 0, 1 pigment { checker red 1 rgb <0, 0, 1> } }
sphere { 0, 1 pigment { checker color Orange blue 1 color rgb 0.5 } }
sphere { 0, 1 pigment { Stripes rgb <0, 1, 0> } }  // a declared pigment, then a colour
// Where a colour is expected, components may follow any expression and
// override it (POV-Ray 3.7 renders these): a declared colour, an arithmetic one.
sphere { 0, 1 pigment { Orange green 1 } }
sphere { 0, 1 pigment { Orange * 0.5 blue 1 } finish { ambient Orange red 0 } }
sphere { 0, 1 pigment { checker Orange green 1, Orange transmit 0 } }
