// Comparisons need parentheses, as in POV-Ray.
#declare Big = 2 > 1;
