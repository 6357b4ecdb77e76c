// noise_generator beyond int.
global_settings { noise_generator 1e10 }
