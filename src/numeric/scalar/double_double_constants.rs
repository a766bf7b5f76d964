//! Mathematical constants in double-double: each is the pair `hi + lo` nearest the true
//! value (`hi` the nearest `f64`, `lo` the nearest `f64` to the remainder), so each is
//! within about 2^-107 relative of the constant. The pairs (and the three-part splits used
//! for argument reduction) were computed with 400-bit arithmetic (mpmath); `hi` is the
//! standard library's constant, `lo` is written as the shortest decimal that rounds to it.
//!
//! Also [`num_traits::FloatConst`] for [`DoubleDouble`], so generic code gets the same pairs.

use super::double_double::DoubleDouble;
use num_traits::FloatConst;
use std::f64::consts;

impl DoubleDouble {
    /// A pair `hi + lo` given with `|lo| ≤ ulp(hi)/2` (not checked).
    pub(super) const fn from_parts(hi: f64, lo: f64) -> Self {
        Self { hi, lo }
    }

    /// e.
    pub const E: Self = Self::from_parts(consts::E, 1.4456468917292502e-16);
    /// ln 2.
    pub const LN_2: Self = Self::from_parts(consts::LN_2, 2.3190468138462996e-17);
    /// ln 10.
    pub const LN_10: Self = Self::from_parts(consts::LN_10, -2.1707562233822494e-16);
    /// log₂ e.
    pub const LOG2_E: Self = Self::from_parts(consts::LOG2_E, 2.0355273740931033e-17);
    /// log₁₀ e.
    pub const LOG10_E: Self = Self::from_parts(consts::LOG10_E, 1.098319650216765e-17);
    /// log₂ 10.
    pub const LOG2_10: Self = Self::from_parts(consts::LOG2_10, 1.661617516973592e-16);
    /// log₁₀ 2.
    pub const LOG10_2: Self = Self::from_parts(consts::LOG10_2, -2.8037281277851704e-18);
    /// 2π.
    pub const TAU: Self = Self::from_parts(consts::TAU, 2.4492935982947064e-16);
    /// π/2.
    pub const FRAC_PI_2: Self = Self::from_parts(consts::FRAC_PI_2, 6.123233995736766e-17);
    /// π/3.
    pub const FRAC_PI_3: Self = Self::from_parts(consts::FRAC_PI_3, -1.072081766451091e-16);
    /// π/4.
    pub const FRAC_PI_4: Self = Self::from_parts(consts::FRAC_PI_4, 3.061616997868383e-17);
    /// π/6.
    pub const FRAC_PI_6: Self = Self::from_parts(consts::FRAC_PI_6, -5.360408832255455e-17);
    /// π/8.
    pub const FRAC_PI_8: Self = Self::from_parts(consts::FRAC_PI_8, 1.5308084989341915e-17);
    /// 1/π.
    pub const FRAC_1_PI: Self = Self::from_parts(consts::FRAC_1_PI, -1.9678676675182486e-17);
    /// 2/π.
    pub const FRAC_2_PI: Self = Self::from_parts(consts::FRAC_2_PI, -3.935735335036497e-17);
    /// 2/√π.
    pub const FRAC_2_SQRT_PI: Self =
        Self::from_parts(consts::FRAC_2_SQRT_PI, 1.533545961316588e-17);
    /// √2.
    pub const SQRT_2: Self = Self::from_parts(consts::SQRT_2, -9.667293313452913e-17);
    /// 1/√2.
    pub const FRAC_1_SQRT_2: Self = Self::from_parts(consts::FRAC_1_SQRT_2, -4.833646656726457e-17);
    /// Degrees per radian, 180/π.
    pub const DEGREES_PER_RADIAN: Self =
        Self::from_parts(57.29577951308232, -1.9878495670576283e-15);
    /// Radians per degree, π/180.
    pub const RADIANS_PER_DEGREE: Self =
        Self::from_parts(0.017453292519943295, 2.9486522708701687e-19);
}

/// π/2 as three `f64` (their sum is within 2^-160 of π/2): a multiple `k·π/2` with an
/// integer `k < 2^53` is then the sum of three exact products.
pub(super) const FRAC_PI_2_PARTS: [f64; 3] = [
    consts::FRAC_PI_2,
    6.123233995736766e-17,
    -1.4973849048591698e-33,
];

/// ln 2 as three `f64` (their sum is within 2^-160 of ln 2).
pub(super) const LN_2_PARTS: [f64; 3] =
    [consts::LN_2, 2.3190468138462996e-17, 5.707708438416212e-34];

impl FloatConst for DoubleDouble {
    fn E() -> Self {
        Self::E
    }
    fn FRAC_1_PI() -> Self {
        Self::FRAC_1_PI
    }
    fn FRAC_1_SQRT_2() -> Self {
        Self::FRAC_1_SQRT_2
    }
    fn FRAC_2_PI() -> Self {
        Self::FRAC_2_PI
    }
    fn FRAC_2_SQRT_PI() -> Self {
        Self::FRAC_2_SQRT_PI
    }
    fn FRAC_PI_2() -> Self {
        Self::FRAC_PI_2
    }
    fn FRAC_PI_3() -> Self {
        Self::FRAC_PI_3
    }
    fn FRAC_PI_4() -> Self {
        Self::FRAC_PI_4
    }
    fn FRAC_PI_6() -> Self {
        Self::FRAC_PI_6
    }
    fn FRAC_PI_8() -> Self {
        Self::FRAC_PI_8
    }
    fn LN_10() -> Self {
        Self::LN_10
    }
    fn LN_2() -> Self {
        Self::LN_2
    }
    fn LOG10_E() -> Self {
        Self::LOG10_E
    }
    fn LOG2_E() -> Self {
        Self::LOG2_E
    }
    fn PI() -> Self {
        Self::PI
    }
    fn SQRT_2() -> Self {
        Self::SQRT_2
    }
    fn TAU() -> Self {
        Self::TAU
    }
    fn LOG10_2() -> Self {
        Self::LOG10_2
    }
    fn LOG2_10() -> Self {
        Self::LOG2_10
    }
}
