// A handle that is not declared, one in use, and a value #write cannot write.
#read (Nothing, A)
#declare Used = 1;
#fopen Used "diag_file_handles.txt" write
#fopen Log "diag_file_handles.txt" write
#write (Log, "colour: ", rgb <1, 0, 0>)
#fclose Used
sphere { 0, 1 }
