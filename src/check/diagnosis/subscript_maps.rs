//! Maps of symbols by their subscripts, applied to an expression: a permutation of the
//! axes x, y, z (every axis subscript at once: `ω_x → ω_y`, `I_xz → I_yx = I_xy`), and a
//! transposition of two symbols (`I_xz ↔ I_yz`).
//!
//! An axis subscript is one or two of the letters `x y z` (`w_x`, `wdot_z`, `I_xy`); a
//! two-letter one is written in the chapter's order, its letters sorted (`I_xy`, `I_yz`,
//! `I_xz`). Other subscripts (`w_1`, `x'`) are not axes and stay.

use crate::algebra::{AlgebraError, Expr, Symbol};

/// A permutation of the axes: `image[a]` is the axis `a` goes to (0 = x, 1 = y, 2 = z).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct AxisPermutation {
    image: [u8; 3],
}

const AXES: [char; 3] = ['x', 'y', 'z'];

impl AxisPermutation {
    /// x → y → z → x.
    pub const CYCLIC: AxisPermutation = AxisPermutation { image: [1, 2, 0] };
    /// x → z → y → x.
    pub const ANTICYCLIC: AxisPermutation = AxisPermutation { image: [2, 0, 1] };
    /// The five permutations other than the identity: the two cycles, then x↔y, y↔z, x↔z.
    pub const NOT_IDENTITY: [AxisPermutation; 5] = [
        AxisPermutation::CYCLIC,
        AxisPermutation::ANTICYCLIC,
        AxisPermutation { image: [1, 0, 2] },
        AxisPermutation { image: [0, 2, 1] },
        AxisPermutation { image: [2, 1, 0] },
    ];

    /// The permutation in words: `x->y, y->z, z->x`.
    pub fn describe(self) -> String {
        AXES.iter()
            .zip(self.image)
            .map(|(from, to)| format!("{from}->{}", AXES[usize::from(to)]))
            .collect::<Vec<_>>()
            .join(", ")
    }

    /// The symbol with its axis subscript permuted (module documentation), or itself.
    pub fn symbol(self, s: Symbol) -> Symbol {
        let subscript = s.subscript();
        let axes: Option<Vec<char>> = subscript
            .chars()
            .map(|c| {
                AXES.iter()
                    .position(|&a| a == c)
                    .map(|a| AXES[usize::from(self.image[a])])
            })
            .collect();
        match axes {
            Some(mut axes) if (1..=2).contains(&axes.len()) => {
                axes.sort_unstable();
                let stem = &s.name()[..s.name().len() - subscript.len()];
                Symbol::new(&format!("{stem}{}", axes.into_iter().collect::<String>()))
            }
            _ => s,
        }
    }

    /// `e` with every axis subscript permuted.
    pub fn apply(self, e: &Expr) -> Result<Expr, AlgebraError> {
        let moved: Vec<(Symbol, Expr)> = e
            .symbols()
            .into_iter()
            .map(|s| (s, self.symbol(s)))
            .filter(|(s, image)| s != image)
            .map(|(s, image)| (s, Expr::sym(image)))
            .collect();
        substitute(e, &moved)
    }

    /// How many distinct symbols of `e` the permutation moves.
    pub fn moved_symbols(self, e: &Expr) -> usize {
        e.symbols()
            .into_iter()
            .filter(|&s| self.symbol(s) != s)
            .count()
    }
}

/// `e` with the symbols `s` and `t` exchanged.
pub(super) fn transpose(e: &Expr, s: Symbol, t: Symbol) -> Result<Expr, AlgebraError> {
    substitute(e, &[(s, Expr::sym(t)), (t, Expr::sym(s))])
}

/// The name of a symbol without its subscript (`I_` for `I_xz`, `wdot_` for `wdot_x`):
/// two symbols with one stem and different subscripts are candidates for a swap.
pub(super) fn stem(s: Symbol) -> &'static str {
    &s.name()[..s.name().len() - s.subscript().len()]
}

/// `e` with each symbol of `values` replaced by its value, all at once.
pub(super) fn substitute(e: &Expr, values: &[(Symbol, Expr)]) -> Result<Expr, AlgebraError> {
    e.subs(&|s| {
        values
            .iter()
            .find(|(from, _)| *from == s)
            .map(|(_, to)| to.clone())
    })
}
