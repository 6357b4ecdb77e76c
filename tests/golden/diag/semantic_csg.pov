// A CSG needs an object (a light is none); the objects of a difference come
// before its modifiers.
difference { pigment { rgb 1 } }
intersection { light_source { <0, 1, 0>, rgb 1 } }
difference { sphere { 0, 1 } translate x box { 0, 1 } }
