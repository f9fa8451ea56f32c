//! Beyond the paper: the set of valid signed radii for a fixed centre.
