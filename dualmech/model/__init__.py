"""What a problem is made of: frames, bodies, the two forms, equations, declarations."""
