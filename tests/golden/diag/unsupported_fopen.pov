// Reading and writing files is not part of the asos language.
#fopen Log "log.txt" write
