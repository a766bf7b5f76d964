//! kinetics: kinetics of rigid bodies in three dimensions.
