// emitter outside a light's asos block.
global_settings { asos { emitter panel } }
