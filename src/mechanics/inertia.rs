//! The inertia tensor in the chapter's convention.
//!
//! Moments `I_x = ∫(y² + z²) dm` and products `I_xy = ∫xy dm` (positive integrals); the
//! tensor is
//!
//! ```text
//!       [  I_x  -I_xy  -I_xz ]
//! [I] = [ -I_xy   I_y  -I_yz ]
//!       [ -I_xz  -I_yz   I_z ]
//! ```
//!
//! Rotation into other axes is `[I'] = R [I] Rᵀ` (R's rows are the new axes in the old
//! frame); the parallel-axis theorem moves a centroidal tensor to a point at `r̄` from G:
//! `I_x = Ī_x + m(ȳ² + z̄²)`, `I_xy = Ī_xy + m x̄ ȳ`; composite bodies add tensors about a
//! common point.

use super::derivation::Relation;
use crate::algebra::{AlgebraError, Axis, Expr, Matrix, Vector};

/// An inertia tensor by its six components: products of inertia are the positive integrals
/// `∫xy dm`, entered in the matrix with a minus sign.
#[derive(Debug, Clone, PartialEq)]
pub struct InertiaTensor {
    /// `[I_x, I_y, I_z]`.
    pub moments: [Expr; 3],
    /// `[I_xy, I_yz, I_xz]` (positive-integral convention).
    pub products: [Expr; 3],
}

/// A part of a body: its mass, the position of its mass centre from O, and its centroidal
/// inertia in the frame's axes.
#[derive(Debug, Clone, PartialEq)]
pub struct MassPart {
    pub mass: Expr,
    pub position: Vector,
    pub inertia: InertiaTensor,
}

impl InertiaTensor {
    /// The general tensor with symbols `I_x, I_y, I_z, I_xy, I_yz, I_xz`.
    pub fn general() -> InertiaTensor {
        InertiaTensor {
            moments: ["I_x", "I_y", "I_z"].map(Expr::symbol),
            products: ["I_xy", "I_yz", "I_xz"].map(Expr::symbol),
        }
    }

    /// Principal axes: symbols `I_x, I_y, I_z`, every product zero.
    pub fn principal() -> InertiaTensor {
        InertiaTensor::diagonal(["I_x", "I_y", "I_z"].map(Expr::symbol))
    }

    pub fn diagonal(moments: [Expr; 3]) -> InertiaTensor {
        InertiaTensor {
            moments,
            products: [Expr::zero(), Expr::zero(), Expr::zero()],
        }
    }

    /// Whether every product of inertia is zero (the axes are principal).
    pub fn is_principal(&self) -> bool {
        self.products.iter().all(Expr::is_zero)
    }

    /// `[I]` with the chapter's signs.
    ///
    /// ```
    /// use kinetics::{Expr, InertiaTensor};
    ///
    /// let matrix = InertiaTensor::general().matrix();
    /// let minus_i_xy = -Expr::symbol("I_xy");
    /// assert_eq!((&matrix[(0, 1)], &matrix[(1, 0)]), (&minus_i_xy, &minus_i_xy));
    /// assert_eq!(matrix[(2, 2)], Expr::symbol("I_z"));
    /// assert_eq!(matrix[(1, 2)], -Expr::symbol("I_yz"));
    /// ```
    pub fn matrix(&self) -> Matrix {
        let [ix, iy, iz] = self.moments.clone();
        let [ixy, iyz, ixz] = self.products.clone().map(|p| -p);
        Matrix::new(
            ix,
            ixy.clone(),
            ixz.clone(),
            ixy,
            iy,
            iyz.clone(),
            ixz,
            iyz,
            iz,
        )
    }

    /// The tensor whose matrix is `m` (symmetric; products read as `-m[0][1]`, ...).
    pub fn from_matrix(m: &Matrix) -> InertiaTensor {
        InertiaTensor {
            moments: [m[(0, 0)].clone(), m[(1, 1)].clone(), m[(2, 2)].clone()],
            products: [-&m[(0, 1)], -&m[(1, 2)], -&m[(0, 2)]],
        }
    }

    /// The tensor in axes whose directions are the rows of `rotation`: `R [I] Rᵀ`, each
    /// component expanded. Fails when a component's expansion is over the bound.
    ///
    /// A quarter turn about z, new axes `x' = y`, `y' = -x`, `z' = z`: the moments about x
    /// and y swap, and `I_x'y' = ∫y(-x) dm = -I_xy`, `I_y'z' = ∫(-x)z dm = -I_xz`,
    /// `I_x'z' = ∫yz dm = I_yz`.
    ///
    /// ```
    /// use kinetics::{Expr, InertiaTensor, Matrix};
    ///
    /// let (o, l) = (Expr::zero(), Expr::one());
    /// #[rustfmt::skip]
    /// let quarter_turn = Matrix::new(
    ///     o.clone(), l.clone(), o.clone(),
    ///     -&l,       o.clone(), o.clone(),
    ///     o.clone(), o.clone(), l.clone(),
    /// );
    /// let turned = InertiaTensor::general().rotated(&quarter_turn)?;
    /// assert_eq!(turned.moments, ["I_y", "I_x", "I_z"].map(Expr::symbol));
    /// let s = Expr::symbol;
    /// assert_eq!(turned.products, [-s("I_xy"), -s("I_xz"), s("I_yz")]);
    /// # Ok::<(), kinetics::AlgebraError>(())
    /// ```
    pub fn rotated(&self, rotation: &Matrix) -> Result<InertiaTensor, AlgebraError> {
        let m = rotation * self.matrix() * rotation.transpose();
        let expanded: Vec<Expr> = m.iter().map(Expr::expand).collect::<Result<_, _>>()?;
        Ok(InertiaTensor::from_matrix(&Matrix::from_iterator(expanded)))
    }

    /// Moves a centroidal tensor to axes through a point O, parallel to the centroidal
    /// ones, where `centroid` is the position of G from O:
    /// `I_x = Ī_x + m(ȳ² + z̄²)`, `I_xy = Ī_xy + m x̄ ȳ`, and cyclically.
    ///
    /// A solid sphere (`Ī = 2/5 m r²` about every centroidal axis) whose centre is at
    /// `(a, b, 0)` from O: `I_x = Ī + m b²`, `I_y = Ī + m a²`, `I_z = Ī + m(a² + b²)`,
    /// `I_xy = m a b`, `I_yz = I_xz = 0`.
    ///
    /// ```
    /// use kinetics::{parse_expression, Expr, InertiaTensor, Vector};
    ///
    /// let hand = |t: &str| parse_expression("by hand", t).unwrap().expand().unwrap();
    /// let sphere = InertiaTensor::diagonal([(); 3].map(|_| hand("2/5 m r^2")));
    /// let centre = Vector::new(Expr::symbol("a"), Expr::symbol("b"), Expr::zero());
    /// let about_o = sphere.parallel_axis(&Expr::symbol("m"), &centre);
    /// let expanded = |c: [Expr; 3]| c.map(|e| e.expand().unwrap());
    /// assert_eq!(
    ///     expanded(about_o.moments),
    ///     ["2/5 m r^2 + m b^2", "2/5 m r^2 + m a^2", "2/5 m r^2 + m (a^2 + b^2)"].map(hand)
    /// );
    /// assert_eq!(expanded(about_o.products), ["m a b", "0", "0"].map(hand));
    /// ```
    pub fn parallel_axis(&self, mass: &Expr, centroid: &Vector) -> InertiaTensor {
        if super::slip::Slip::ParallelAxisMissing.is_active() {
            return self.clone();
        }
        let [x, y, z] = [&centroid[0], &centroid[1], &centroid[2]];
        let sq = |a: &Expr| a * a;
        let shift_moments = [sq(y) + sq(z), sq(z) + sq(x), sq(x) + sq(y)];
        let shift_products = [x * y, y * z, x * z];
        InertiaTensor {
            moments: std::array::from_fn(|k| &self.moments[k] + &(mass * &shift_moments[k])),
            products: std::array::from_fn(|k| &self.products[k] + &(mass * &shift_products[k])),
        }
    }

    /// The centroidal tensor of a body made of `parts`, whose total `mass` has its centre at
    /// `centroid`: each part's centroidal tensor moved to O, their sum, moved back to G.
    /// Each component expanded.
    pub fn composite(
        parts: &[MassPart],
        mass: &Expr,
        centroid: &Vector,
    ) -> Result<InertiaTensor, AlgebraError> {
        let about_o = parts
            .iter()
            .map(|p| p.inertia.parallel_axis(&p.mass, &p.position))
            .fold(InertiaTensor::zero(), |sum, part| sum.add(&part));
        about_o.parallel_axis(&-mass, centroid).expanded()
    }

    /// The six relations `I_x = …`, `I_y = …`, `I_z = …`, `I_xy = …`, `I_yz = …`, `I_xz = …`
    /// that show the tensor in a step.
    pub fn relations(&self) -> Vec<Relation> {
        ["I_x", "I_y", "I_z"]
            .into_iter()
            .zip(&self.moments)
            .chain(["I_xy", "I_yz", "I_xz"].into_iter().zip(&self.products))
            .map(|(name, value)| Relation::new(Expr::symbol(name), value.clone(), Axis::X))
            .collect()
    }

    /// How a title writes the tensor about `point` (title markup): `[I]` about the mass
    /// centre G, `[I_O]` about a fixed point O, as the chapter does.
    pub fn written_about(point: &str) -> String {
        match point {
            "G" => "[I]".to_string(),
            _ => format!("[I_{point}]"),
        }
    }

    /// The tensor of no mass: every moment and product zero.
    pub fn zero() -> InertiaTensor {
        InertiaTensor::diagonal([Expr::zero(), Expr::zero(), Expr::zero()])
    }

    /// The same tensor with each component multiplied out ([`Expr::expand`]).
    pub fn expanded(&self) -> Result<InertiaTensor, AlgebraError> {
        let expand = |c: &[Expr; 3]| -> Result<[Expr; 3], AlgebraError> {
            Ok([c[0].expand()?, c[1].expand()?, c[2].expand()?])
        };
        Ok(InertiaTensor {
            moments: expand(&self.moments)?,
            products: expand(&self.products)?,
        })
    }

    /// The tensor of two parts about the same point and axes.
    pub fn add(&self, other: &InertiaTensor) -> InertiaTensor {
        InertiaTensor {
            moments: std::array::from_fn(|k| &self.moments[k] + &other.moments[k]),
            products: std::array::from_fn(|k| &self.products[k] + &other.products[k]),
        }
    }
}
