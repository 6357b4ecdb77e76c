// clipped_by and bounded_by misused: POV-Ray's own refusals.
sphere { 0, 1 clipped_by { box { -1, 1 pigment { rgb 1 } } } }
sphere { 0, 1 clipped_by { triangle { -x, x, y } } }
sphere { 0, 1 clipped_by { bounded_by } }
sphere { 0, 1 bounded_by { box { -1, 1 } } clipped_by { bounded_by } bounded_by { box { -2, 2 } } }
sphere { 0, 1 clipped_by { box { -1, 1 } } clipped_by { bounded_by } }
sphere { 0, 1 clipped_by { translate x } }
sphere { 0, 1 clipped_by { box { -1, 1 } translate x sphere { 0, 1 } } }
sphere { 0, 1 clipped_by { } }
sphere { 0, 1 clipped_by { light_source { 0, 1 } } }
