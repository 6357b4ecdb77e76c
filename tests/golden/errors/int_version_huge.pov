// A #version beyond any POV-Ray.
#version 1e300;
