// A file to read that is in none of the folders looked in.
#fopen Data "no_such_data.txt" read
sphere { 0, 1 }
