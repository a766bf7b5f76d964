//! A student's slip as a variant of the mechanics: the derivation run again with one piece
//! of it done the way the slip does it, so that the checker can say which slip turns the
//! correct value into the one claimed (`check::slip_reading`). One slip at a time is
//! active on a thread, while [`Slip::applied`] runs; the pieces read it where they are
//! formed, and nowhere else:
//!
//! ```text
//! transport-term-missing      Ḣ = [I]{ω̇}            for  Ḣ = [I]{ω̇} + Ω × H   rotating_frame.rs
//! omega-for-Omega             ω × H                  for  Ω × H                 rotating_frame.rs
//! cross-product-reversed      H × Ω                  for  Ω × H                 rotating_frame.rs
//! omega-squared-for-omegadot  [I]{ω_x², ω_y², ω_z²}  for  [I]{ω̇}                rotating_frame.rs
//! parallel-axis-missing       Ī                      for  Ī + m(ȳ² + z̄²)        inertia.rs
//! half-missing                ωᵀ[I]ω, m v̄²           for  ½ ωᵀ[I]ω, ½ m v̄²      kinetic_energy.rs
//! wrong-moment-of-inertia     ¼ m r² about the axis  for  ½ m r² (a disk), ⅓ m L² for
//!                             1/12 m L² (a rod about its end for its centre)  shapes.rs
//! ```

use crate::algebra::Expr;
use std::cell::Cell;

/// A slip a student makes in this chapter, as a piece of the derivation done otherwise.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Slip {
    /// The transport term Ω × H left out of Ḣ.
    TransportTermMissing,
    /// ω used in the transport term where the frame's rate Ω belongs.
    OmegaForFrameRate,
    /// H × Ω written for Ω × H.
    CrossProductReversed,
    /// ω² written for ω̇ in [I]{ω̇} (each component squared).
    SquareForRate,
    /// A part's moments of inertia not moved to the reference point: no m(ȳ² + z̄²).
    ParallelAxisMissing,
    /// The ½ of the rotational kinetic energy left out.
    HalfMissingRotation,
    /// The ½ of the translational kinetic energy left out.
    HalfMissingTranslation,
    /// A disk's or cylinder's moment about its axis and about a diameter exchanged.
    AxialAndDiametralExchanged,
    /// A rod's moment about its end (⅓ m L²) used for the one about its centre (1/12 m L²).
    RodAboutEnd,
}

thread_local! {
    static ACTIVE: Cell<Option<Slip>> = const { Cell::new(None) };
}

/// Puts the slip that was active back when dropped (also when the derivation panics).
struct Restore(Option<Slip>);

impl Drop for Restore {
    fn drop(&mut self) {
        ACTIVE.with(|a| a.set(self.0));
    }
}

impl Slip {
    /// Every slip, in the order the checker tries them.
    pub const ALL: [Slip; 9] = [
        Slip::TransportTermMissing,
        Slip::OmegaForFrameRate,
        Slip::CrossProductReversed,
        Slip::SquareForRate,
        Slip::ParallelAxisMissing,
        Slip::HalfMissingRotation,
        Slip::HalfMissingTranslation,
        Slip::AxialAndDiametralExchanged,
        Slip::RodAboutEnd,
    ];

    /// The reading's name, as the checker reports it.
    pub fn name(self) -> &'static str {
        match self {
            Slip::TransportTermMissing => "transport-term-missing",
            Slip::OmegaForFrameRate => "omega-for-Omega",
            Slip::CrossProductReversed => "cross-product-reversed",
            Slip::SquareForRate => "omega-squared-for-omegadot",
            Slip::ParallelAxisMissing => "parallel-axis-missing",
            Slip::HalfMissingRotation | Slip::HalfMissingTranslation => "half-missing",
            Slip::AxialAndDiametralExchanged | Slip::RodAboutEnd => "wrong-moment-of-inertia",
        }
    }

    /// What the slip is, in words a student acts on: a title in the markup subset
    /// (`print::markup`), words with mathematics between `$…$`.
    pub fn concept(self) -> &'static str {
        match self {
            Slip::TransportTermMissing => {
                r"the transport term $\boldsymbol{\Omega} \times \mathbf{H}$ is missing: in a frame turning at $\boldsymbol{\Omega}$, $\dot{\mathbf{H}} = (\dot{\mathbf{H}})_{Oxyz} + \boldsymbol{\Omega} \times \mathbf{H}$"
            }
            Slip::OmegaForFrameRate => {
                r"$\boldsymbol{\omega}$ is used where the frame's rate $\boldsymbol{\Omega}$ belongs: the transport term is $\boldsymbol{\Omega} \times \mathbf{H}$, with the rate of the axes, not of the body"
            }
            Slip::CrossProductReversed => {
                r"the cross product is reversed: the transport term is $\boldsymbol{\Omega} \times \mathbf{H}$, and $\mathbf{H} \times \boldsymbol{\Omega} = -\boldsymbol{\Omega} \times \mathbf{H}$"
            }
            Slip::SquareForRate => {
                r"$\omega^2$ is written where the angular acceleration $\dot{\omega}$ belongs: the rate relative to the frame is $[I]\{\dot{\boldsymbol{\omega}}\}$"
            }
            Slip::ParallelAxisMissing => {
                r"the parallel-axis term is missing: about a point other than $G$ each moment of inertia gains $m(\bar{y}^2 + \bar{z}^2)$, each product $m\bar{x}\bar{y}$"
            }
            Slip::HalfMissingRotation => {
                r"the $\frac{1}{2}$ of the rotational kinetic energy is missing: $T_{rot} = \frac{1}{2}\{\boldsymbol{\omega}\}^T[I]\{\boldsymbol{\omega}\}$"
            }
            Slip::HalfMissingTranslation => {
                r"the $\frac{1}{2}$ of the translational kinetic energy is missing: $T_{trans} = \frac{1}{2} m\bar{v}^2$"
            }
            Slip::AxialAndDiametralExchanged => {
                r"the moments of inertia about the axis and about a diameter are exchanged: a thin disk has $\frac{1}{2} m r^2$ about its axis and $\frac{1}{4} m r^2$ about a diameter"
            }
            Slip::RodAboutEnd => {
                r"the rod's moment of inertia about its end, $\frac{1}{3} m L^2$, is used for the one about its centre, $\frac{1}{12} m L^2$"
            }
        }
    }

    /// `derive()` run with this slip made wherever its piece is formed.
    pub fn applied<T>(self, derive: impl FnOnce() -> T) -> T {
        let _restore = Restore(ACTIVE.with(|a| a.replace(Some(self))));
        derive()
    }

    /// Whether this slip is being made (on this thread).
    pub fn is_active(self) -> bool {
        ACTIVE.with(Cell::get) == Some(self)
    }

    /// The slip being made on this thread, if any.
    pub fn active() -> Option<Slip> {
        ACTIVE.with(Cell::get)
    }
}

/// The factor ½ of a kinetic energy, or 1 while `slip` leaves it out.
pub fn half_unless(slip: Slip) -> Expr {
    if slip.is_active() {
        Expr::one()
    } else {
        Expr::rational(1, 2)
    }
}
