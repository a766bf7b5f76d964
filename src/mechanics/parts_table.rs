//! A composite body's table of parts, as a student lays it out before adding: a row per
//! part (`1`, `2`, …), the columns `m, x̄, ȳ, z̄` (the part's mass and the position of its
//! mass centre from O) and `I_x, I_y, I_z, I_xy, I_yz, I_xz` (the part's moments and
//! products of inertia about the point the body's are taken about).

use super::derivation::{Table, TableRow};
use super::inertia::{InertiaTensor, MassPart};
use crate::algebra::Expr;

/// What the inertia columns of a table hold.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Columns {
    /// Each part's moments and products about the common point (O): their sums are the body's.
    AboutPoint,
    /// Each part's own centroidal moments and products (`Ī_x'`, …), before the parallel-axis
    /// theorem.
    OwnCentroidal,
}

impl Columns {
    fn names(self) -> [&'static str; 10] {
        match self {
            Columns::AboutPoint => [
                "m", "xbar", "ybar", "zbar", "I_x", "I_y", "I_z", "I_xy", "I_yz", "I_xz",
            ],
            Columns::OwnCentroidal => [
                "m",
                "xbar",
                "ybar",
                "zbar",
                "Ibar_x'",
                "Ibar_y'",
                "Ibar_z'",
                "Ibar_x'y'",
                "Ibar_y'z'",
                "Ibar_x'z'",
            ],
        }
    }
}

/// The table of `parts`, each with its tensor `about` the common point (`about[i]` is part
/// i's), each cell as given (the step shows it in its shortest form); `None` for a body of
/// one part, where the table would repeat the sum.
///
/// ```
/// use kinetics::mechanics::inertia::MassPart;
/// use kinetics::mechanics::parts_table::{parts_table, Columns};
/// use kinetics::{Expr, InertiaTensor, Vector};
///
/// let particle = |x: &str| MassPart {
///     mass: Expr::symbol("m"),
///     position: Vector::new(Expr::symbol(x), Expr::zero(), Expr::zero()),
///     inertia: InertiaTensor::diagonal([(); 3].map(|_| Expr::zero())),
/// };
/// let parts = [particle("a"), particle("b")];
/// let about: Vec<InertiaTensor> = parts.iter().map(|p| p.inertia.clone()).collect();
/// let table = parts_table(&parts, &about, Columns::AboutPoint).expect("two parts");
/// assert_eq!(table.columns.len(), 10);
/// assert_eq!(table.rows[1].label, "2");
/// assert_eq!(table.rows[1].cells[1], Expr::symbol("b"));
/// assert!(parts_table(&parts[..1], &about[..1], Columns::AboutPoint).is_none());
/// ```
pub fn parts_table(parts: &[MassPart], about: &[InertiaTensor], columns: Columns) -> Option<Table> {
    if parts.len() < 2 {
        return None;
    }
    let rows = parts
        .iter()
        .zip(about)
        .enumerate()
        .map(|(k, (part, tensor))| {
            let cells = std::iter::once(&part.mass)
                .chain(part.position.iter())
                .chain(&tensor.moments)
                .chain(&tensor.products)
                .cloned()
                .collect();
            TableRow {
                label: (k + 1).to_string(),
                cells,
            }
        })
        .collect();
    Some(Table {
        columns: columns.names().map(Expr::symbol).to_vec(),
        rows,
    })
}
