sphere { Centre, 1 }
