// #read meets a value that is not a float, a vector or a string: the error
// is located in the data file, with the #read that read it.
#fopen Data "diag_data_bad.txt" read
#read (Data, A, B, C)
sphere { 0, 1 }
