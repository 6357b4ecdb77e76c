// POV-Ray's #statistics (a message of its own) is not part of the asos language.
#statistics "done"
