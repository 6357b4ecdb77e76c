difference { box { 0, 1 } sphere { 0, 0.5 } }
