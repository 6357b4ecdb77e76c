// A turbulence value that overflows.
sphere { 0, 1 pigment { granite turbulence 1e308 * 10 } }
