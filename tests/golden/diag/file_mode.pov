// #read of a file opened for writing, and #write to one opened for reading.
#fopen Log "diag_file_mode.txt" write
#read (Log, A)
#fopen Data "golden_data.txt" read
#write (Data, "x")
#fclose Log
sphere { 0, 1 }
