sphere { 0, 1 open }
