// A color_map entry whose value overflows.
sphere { 0, 1 pigment { gradient x color_map { [0 rgb 1] [1e308 * 10 rgb 0] } } }
