global_settings { asos { eps 0 max -1 } }
sphere { 0, 1 asos { eps -0.5 max 2.5 } }
