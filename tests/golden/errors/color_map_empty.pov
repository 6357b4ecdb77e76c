// A color_map without entries.
sphere { 0, 1 pigment { gradient x color_map { } } }
