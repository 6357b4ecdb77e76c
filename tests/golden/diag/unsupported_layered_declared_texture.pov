// A declared layered texture (POV-Ray paints the second over the first)
// is named where the second texture starts.
#declare Layered = texture { pigment { rgb 1 } }
  texture { pigment { bozo } }
