// #fopen, #write, #fclose, #read and file_exists(): values written, read back
// and placed; POV-Ray 3.7 writes and reads the same (checked with povray).
#version 3.7;
#fopen Out "golden_files_out.txt" write
#for (I, 1, 3)
  #write (Out, I / 4, ",", <I, -I, I * 0.5>, ",\"ball ", str(I, 0, 0), "\",\n")
#end
#fclose Out
#fopen In "golden_files_out.txt" read
// Each line ends with a comma, so after the last one a #read more finds the
// end and changes nothing: the last ball is placed twice, as in POV-Ray.
#while (defined(In))
  #read (In, R, Centre, Name)
  sphere { Centre, R }
  #debug concat(Name, "\n")
#end
// A data file beside the include files (-L), read up to its end.
#fopen Data "golden_data.txt" read
#read (Data, A, B, V, S)
#if (defined(Data)) #error "the file should be closed at its end" #end
#fclose Data
box { <A, B, 0>, V }
sphere { <file_exists("golden_data.txt"), file_exists("no_such_file.txt"), strlen(S)>, 0.5 }
