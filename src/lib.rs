//! kinetics: kinetics of rigid bodies in three dimensions.

pub mod mechanics;
pub mod numeric;
