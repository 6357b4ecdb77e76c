// #fopen without its mode.
#fopen Data "golden_data.txt"
sphere { 0, 1 }
