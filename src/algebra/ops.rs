//! Arithmetic operators on [`Expr`], so that `nalgebra::Matrix3<Expr> * Vector3<Expr>` and
//! `Vector3::cross` work and derivations read like the mathematics.
//!
//! Division by an expression that is exactly zero panics, as integer division does; input
//! from users goes through [`Expr::checked_div`], which returns an error instead.

use super::expr::Expr;
use super::merge;
use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};

impl Add<&Expr> for &Expr {
    type Output = Expr;
    fn add(self, rhs: &Expr) -> Expr {
        if self.is_zero() {
            return rhs.clone();
        }
        if rhs.is_zero() {
            return self.clone();
        }
        merge::sum(self, rhs)
    }
}

impl Mul<&Expr> for &Expr {
    type Output = Expr;
    fn mul(self, rhs: &Expr) -> Expr {
        if self.is_one() {
            return rhs.clone();
        }
        if rhs.is_one() {
            return self.clone();
        }
        merge::product(self, rhs)
    }
}

impl Neg for &Expr {
    type Output = Expr;
    fn neg(self) -> Expr {
        merge::product(&Expr::int(-1), self)
    }
}

impl Sub<&Expr> for &Expr {
    type Output = Expr;
    fn sub(self, rhs: &Expr) -> Expr {
        self + &(-rhs)
    }
}

impl Div<&Expr> for &Expr {
    type Output = Expr;
    fn div(self, rhs: &Expr) -> Expr {
        self.checked_div(rhs).expect("division by zero")
    }
}

impl Neg for Expr {
    type Output = Expr;
    fn neg(self) -> Expr {
        -&self
    }
}

/// Owned sums and products hand back an operand that meets the identity (`0 + x`, `1 · x`)
/// without copying it; nalgebra's matrix products are made of such steps.
impl Add<Expr> for Expr {
    type Output = Expr;
    fn add(self, rhs: Expr) -> Expr {
        match (self.is_zero(), rhs.is_zero()) {
            (true, _) => rhs,
            (_, true) => self,
            _ => merge::sum(&self, &rhs),
        }
    }
}

impl Mul<Expr> for Expr {
    type Output = Expr;
    fn mul(self, rhs: Expr) -> Expr {
        match (self.is_one(), rhs.is_one()) {
            (true, _) => rhs,
            (_, true) => self,
            _ => merge::product(&self, &rhs),
        }
    }
}

impl Sub<Expr> for Expr {
    type Output = Expr;
    fn sub(self, rhs: Expr) -> Expr {
        &self - &rhs
    }
}

impl Div<Expr> for Expr {
    type Output = Expr;
    fn div(self, rhs: Expr) -> Expr {
        &self / &rhs
    }
}

/// The mixed and assigning forms of a binary operator, all through the `&Expr` form.
macro_rules! forward_binary {
    ($Trait:ident, $method:ident, $AssignTrait:ident, $assign:ident) => {
        impl $Trait<&Expr> for Expr {
            type Output = Expr;
            fn $method(self, rhs: &Expr) -> Expr {
                (&self).$method(rhs)
            }
        }
        impl $Trait<Expr> for &Expr {
            type Output = Expr;
            fn $method(self, rhs: Expr) -> Expr {
                self.$method(&rhs)
            }
        }
        impl $AssignTrait<Expr> for Expr {
            fn $assign(&mut self, rhs: Expr) {
                *self = (&*self).$method(&rhs);
            }
        }
        impl $AssignTrait<&Expr> for Expr {
            fn $assign(&mut self, rhs: &Expr) {
                *self = (&*self).$method(rhs);
            }
        }
    };
}

forward_binary!(Add, add, AddAssign, add_assign);
forward_binary!(Sub, sub, SubAssign, sub_assign);
forward_binary!(Mul, mul, MulAssign, mul_assign);
forward_binary!(Div, div, DivAssign, div_assign);

impl num_traits::Zero for Expr {
    fn zero() -> Expr {
        Expr::zero()
    }
    fn is_zero(&self) -> bool {
        Expr::is_zero(self)
    }
}

impl num_traits::One for Expr {
    fn one() -> Expr {
        Expr::one()
    }
}

impl std::iter::Sum for Expr {
    fn sum<I: Iterator<Item = Expr>>(iter: I) -> Expr {
        Expr::add_all(iter)
    }
}

impl std::iter::Product for Expr {
    fn product<I: Iterator<Item = Expr>>(iter: I) -> Expr {
        Expr::mul_all(iter)
    }
}
