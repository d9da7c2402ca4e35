"""The product's kernel: the inversion of the motion, the flat face's envelope, extremum searches."""
