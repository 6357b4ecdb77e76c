// POV-Ray refuses ?: inside a function; select chooses.
#declare F = function { x > 0 ? 1 : 0 }
