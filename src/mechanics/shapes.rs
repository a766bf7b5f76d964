//! Centroidal inertia of the standard shapes, each in its own axes.
//!
//! | shape | axes | moments |
//! |---|---|---|
//! | slender rod, length L | along x | `0, mL²/12, mL²/12` |
//! | thin rectangular plate a × b | sides along x (a), y (b), normal z | `mb²/12, ma²/12, m(a²+b²)/12` |
//! | thin disk, radius r | axis x | `mr²/2, mr²/4, mr²/4` |
//! | solid cylinder, radius r, length h | axis x | `mr²/2, m(3r²+h²)/12, m(3r²+h²)/12` |
//! | solid sphere, radius r | any | `2mr²/5` each |
//! | rectangular prism a × b × c | edges along x, y, z | `m(b²+c²)/12, m(c²+a²)/12, m(a²+b²)/12` |
//! | solid cone, base radius r, height h | axis x, apex to base | `3mr²/10, 3m(4r²+h²)/80, 3m(4r²+h²)/80` |
//! | hollow cylinder (tube), radii r_o > r_i, length h | axis x | `m(r_o²+r_i²)/2, m(3(r_o²+r_i²)+h²)/12, …` |
//! | thin spherical shell, radius r | any | `2mr²/3` each |
//! | thin ring, radius r | axis x | `mr², mr²/2, mr²/2` |
//! | radii of gyration k_x, k_y, k_z | x, y, z | `m k_x², m k_y², m k_z²` |
//! | point mass | any | `0, 0, 0` |
//!
//! A cone is placed, like every shape, by its mass centre G, which lies on its axis a quarter
//! of the height from the base: its apex is ¾h behind G (at x = −3h/4), so about a transverse
//! axis through the apex `3m(4r²+h²)/80 + m(3h/4)² = 3m(r²/4 + h²)/5`.
//!
//! All products of inertia are zero in these axes (they are principal by symmetry). A body
//! may also be given by its six centroidal components ([`Shape::Explicit`]).

use super::inertia::InertiaTensor;
use super::slip::Slip;
use crate::algebra::{AlgebraError, Expr};

/// A body whose inertia is known in closed form.
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    SlenderRod {
        length: Expr,
    },
    ThinPlate {
        a: Expr,
        b: Expr,
    },
    ThinDisk {
        radius: Expr,
    },
    SolidCylinder {
        radius: Expr,
        length: Expr,
    },
    SolidSphere {
        radius: Expr,
    },
    RectangularPrism {
        a: Expr,
        b: Expr,
        c: Expr,
    },
    /// A solid right circular cone, its axis along x from the apex to the base.
    SolidCone {
        radius: Expr,
        height: Expr,
    },
    /// A hollow circular cylinder (a tube), its axis along x; `inner` is less than `outer`.
    Tube {
        outer: Expr,
        inner: Expr,
        length: Expr,
    },
    /// A thin spherical shell.
    SphericalShell {
        radius: Expr,
    },
    /// A thin circular ring (a hoop), its axis along x.
    ThinRing {
        radius: Expr,
    },
    /// A body given by its centroidal radii of gyration about its own axes x, y, z (principal).
    Gyration {
        radii: [Expr; 3],
    },
    PointMass,
    /// A body whose centroidal moments `[I_x, I_y, I_z]` and products `[I_xy, I_yz, I_xz]`
    /// (positive-integral convention) are given directly.
    Explicit(InertiaTensor),
}

impl Shape {
    /// The radius of a round shape (its outer radius for a tube), none for the others.
    pub fn radius(&self) -> Option<&Expr> {
        match self {
            Shape::ThinDisk { radius }
            | Shape::SolidCylinder { radius, .. }
            | Shape::SolidSphere { radius }
            | Shape::SolidCone { radius, .. }
            | Shape::SphericalShell { radius }
            | Shape::ThinRing { radius }
            | Shape::Tube { outer: radius, .. } => Some(radius),
            _ => None,
        }
    }

    /// The lengths that define the shape, in the order they are written, each with what it
    /// is (`radius`, `length`, `side`): all of them must be positive.
    pub fn lengths(&self) -> Vec<(&'static str, &Expr)> {
        match self {
            Shape::SlenderRod { length } => vec![("length", length)],
            Shape::ThinPlate { a, b } => vec![("side", a), ("side", b)],
            Shape::ThinDisk { radius }
            | Shape::SolidSphere { radius }
            | Shape::SphericalShell { radius }
            | Shape::ThinRing { radius } => vec![("radius", radius)],
            Shape::SolidCylinder { radius, length } => {
                vec![("radius", radius), ("length", length)]
            }
            Shape::SolidCone { radius, height } => vec![("radius", radius), ("height", height)],
            Shape::Tube {
                outer,
                inner,
                length,
            } => vec![
                ("outer radius", outer),
                ("inner radius", inner),
                ("length", length),
            ],
            Shape::Gyration { radii } => radii.iter().map(|k| ("radius of gyration", k)).collect(),
            Shape::RectangularPrism { a, b, c } => vec![("side", a), ("side", b), ("side", c)],
            Shape::PointMass | Shape::Explicit(_) => vec![],
        }
    }

    /// The centroidal tensor of this shape with mass `m`, in the shape's own axes, each
    /// moment expanded. Fails when a moment's expansion is over the bound (dimensions given
    /// as large powers of sums).
    ///
    /// ```
    /// use kinetics::mechanics::shapes::Shape;
    /// use kinetics::{parse_expression, Expr};
    ///
    /// // A solid cylinder: m r²/2 about its axis x, m(3r² + h²)/12 across it.
    /// let (r, h) = (Expr::symbol("r"), Expr::symbol("h"));
    /// let cylinder = Shape::SolidCylinder { radius: r, length: h };
    /// let inertia = cylinder.centroidal_inertia(&Expr::symbol("m"))?;
    /// let hand = |t: &str| parse_expression("by hand", t).unwrap().expand().unwrap();
    /// let across = hand("m (3 r^2 + h^2)/12");
    /// assert_eq!(inertia.moments, [hand("m r^2/2"), across.clone(), across]);
    /// assert!(inertia.is_principal());
    /// # Ok::<(), kinetics::AlgebraError>(())
    /// ```
    pub fn centroidal_inertia(&self, m: &Expr) -> Result<InertiaTensor, AlgebraError> {
        let q = |n: i64, d: i64| Expr::rational(n, d) * m;
        let sq = |e: &Expr| e.powi(2);
        let moments = match self {
            Shape::SlenderRod { length } => {
                let twelfth = match Slip::RodAboutEnd.is_active() {
                    true => q(1, 3),
                    false => q(1, 12),
                };
                let i = twelfth * sq(length);
                [Expr::zero(), i.clone(), i]
            }
            Shape::ThinPlate { a, b } => [
                q(1, 12) * sq(b),
                q(1, 12) * sq(a),
                q(1, 12) * (sq(a) + sq(b)),
            ],
            Shape::ThinDisk { radius } => [
                q(1, 2) * sq(radius),
                q(1, 4) * sq(radius),
                q(1, 4) * sq(radius),
            ],
            Shape::SolidCylinder { radius, length } => {
                let transverse = q(1, 12) * (Expr::int(3) * sq(radius) + sq(length));
                [q(1, 2) * sq(radius), transverse.clone(), transverse]
            }
            Shape::SolidSphere { radius } => {
                let i = q(2, 5) * sq(radius);
                [i.clone(), i.clone(), i]
            }
            Shape::RectangularPrism { a, b, c } => [
                q(1, 12) * (sq(b) + sq(c)),
                q(1, 12) * (sq(c) + sq(a)),
                q(1, 12) * (sq(a) + sq(b)),
            ],
            Shape::SolidCone { radius, height } => {
                let transverse = q(3, 80) * (Expr::int(4) * sq(radius) + sq(height));
                [q(3, 10) * sq(radius), transverse.clone(), transverse]
            }
            Shape::Tube {
                outer,
                inner,
                length,
            } => {
                let radii = sq(outer) + sq(inner);
                let transverse = q(1, 12) * (Expr::int(3) * radii.clone() + sq(length));
                [q(1, 2) * radii, transverse.clone(), transverse]
            }
            Shape::SphericalShell { radius } => {
                let i = q(2, 3) * sq(radius);
                [i.clone(), i.clone(), i]
            }
            Shape::ThinRing { radius } => [
                q(1, 1) * sq(radius),
                q(1, 2) * sq(radius),
                q(1, 2) * sq(radius),
            ],
            Shape::Gyration { radii } => radii.clone().map(|k| q(1, 1) * sq(&k)),
            Shape::PointMass => [Expr::zero(), Expr::zero(), Expr::zero()],
            Shape::Explicit(tensor) => return Ok(tensor.clone()),
        };
        let [x, y, z] = moments.map(|e| e.expand());
        let [x, y, z] = [x?, y?, z?];
        let axisymmetric = matches!(
            self,
            Shape::ThinDisk { .. }
                | Shape::SolidCylinder { .. }
                | Shape::SolidCone { .. }
                | Shape::Tube { .. }
                | Shape::ThinRing { .. }
        );
        if axisymmetric && Slip::AxialAndDiametralExchanged.is_active() {
            return Ok(InertiaTensor::diagonal([y, x.clone(), x]));
        }
        Ok(InertiaTensor::diagonal([x, y, z]))
    }
}
