//! A derivation: the result together with the steps that led to it (definition,
//! substitution, grouping), so worked solutions can show them.

use crate::algebra::{Axis, Domains, Expr};

/// One displayed equation `lhs = rhs`, presented as the equation about `axis`.
#[derive(Debug, Clone, PartialEq)]
pub struct Relation {
    pub lhs: Expr,
    pub rhs: Expr,
    pub axis: Axis,
}

impl Relation {
    pub fn new(lhs: Expr, rhs: Expr, axis: Axis) -> Relation {
        Relation { lhs, rhs, axis }
    }

    /// The three component relations `name_x = v[0]`, `name_y = v[1]`, `name_z = v[2]`.
    pub fn components(name: &str, v: &crate::algebra::Vector) -> Vec<Relation> {
        Relation::components_named(v, |sub| format!("{name}_{sub}"))
    }

    /// The three component relations, the left side of each named by `named` from its axis
    /// (`x`, `y`, `z`): `v_Ax = v[0]`, ...
    pub fn components_named(
        v: &crate::algebra::Vector,
        named: impl Fn(&str) -> String,
    ) -> Vec<Relation> {
        [("x", Axis::X), ("y", Axis::Y), ("z", Axis::Z)]
            .iter()
            .zip(v.iter())
            .map(|((sub, axis), rhs)| Relation::new(Expr::symbol(&named(sub)), rhs.clone(), *axis))
            .collect()
    }

    /// The component relations `lhs_k = rhs_k` about the axes x, y, z, without those that
    /// read `0 = 0`.
    pub fn nonzero_components(
        lhs: &crate::algebra::Vector,
        rhs: &crate::algebra::Vector,
    ) -> Vec<Relation> {
        [Axis::X, Axis::Y, Axis::Z]
            .into_iter()
            .enumerate()
            .filter(|&(k, _)| !(lhs[k].is_zero() && rhs[k].is_zero()))
            .map(|(k, axis)| Relation::new(lhs[k].clone(), rhs[k].clone(), axis))
            .collect()
    }

    /// The relation as it is shown: each side in its shortest form ([`Expr::simplify`]) under
    /// the symbols' domains. A side too large to simplify within the algebra's bounds is
    /// shown as derived (it is equal, only longer).
    pub fn simplified(&self, domains: &Domains) -> Relation {
        Relation::new(
            presented(&self.lhs, domains),
            presented(&self.rhs, domains),
            self.axis,
        )
    }

    /// `lhs − rhs`: zero exactly when the relation holds, the form a solver takes.
    pub fn residual(&self) -> Expr {
        &self.lhs - &self.rhs
    }
}

/// A step of a derivation: what was done, in words, and the relations it produced; a
/// composite body's step also lays out its parts' contributions as a table before the sum.
///
/// The title is words with mathematics between `$…$` in the LaTeX subset that
/// `print::markup` reads, so every format typesets it:
/// `r"angular momentum about O, $\mathbf{H}_O = [I_O]\{\boldsymbol{\omega}\}$"`.
#[derive(Debug, Clone, PartialEq)]
pub struct Step {
    pub title: String,
    pub table: Option<Table>,
    /// Vectors with names of their own (`Ω × H_O = I_xy ω² k`), before the relations.
    pub vectors: Vec<VectorRelation>,
    pub relations: Vec<Relation>,
}

/// A vector quantity under the name the chapter gives it and its value, shown as one
/// vector: `(Ḣ_O)_Oxyz = 0`, `Ω × H_O = I_xy ω² k`, `r̄ × m v̄ = …`. A term of a sum
/// is written so, not by components named like the sum's (`Ḣ_x` would name three
/// quantities in three steps).
#[derive(Debug, Clone, PartialEq)]
pub struct VectorRelation {
    /// The name in the LaTeX subset of titles (`\boldsymbol{\Omega} \times \mathbf{H}_O`).
    pub name: String,
    pub value: crate::algebra::Vector,
}

/// A table of a composite body's parts as a student lays it out: a row per part (its label,
/// e.g. `1`, `rod AB`), a column per quantity (headers such as `m`, `xbar`, `I_x`, `I_xy`),
/// each cell that part's contribution; the step's relations then give the sums.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    pub columns: Vec<Expr>,
    pub rows: Vec<TableRow>,
}

/// One part's row of a [`Table`].
#[derive(Debug, Clone, PartialEq)]
pub struct TableRow {
    pub label: String,
    pub cells: Vec<Expr>,
}

/// An expression as it is shown: [`Expr::simplify`], or the expression itself when it is
/// beyond the bounds of simplification; over one denominator when the shortest form holds
/// a fraction inside a fraction or a product (`-¼ m r (4L + r²/L) ω₁` is shown
/// `-m r (4L² + r²) ω₁/(4L)`), as a textbook never nests them.
pub fn presented(e: &Expr, domains: &Domains) -> Expr {
    let shortest = e.simplify(domains).unwrap_or_else(|_| e.clone());
    if !shortest.has_nested_fraction() {
        return shortest;
    }
    match shortest.together() {
        Ok(together) if !together.has_nested_fraction() => together,
        _ => shortest,
    }
}

impl Step {
    /// A step without a table.
    pub fn new(title: impl Into<String>, relations: Vec<Relation>) -> Step {
        Step {
            title: title.into(),
            table: None,
            vectors: Vec::new(),
            relations,
        }
    }

    /// A step that finds one named vector.
    pub fn vector(
        title: impl Into<String>,
        name: impl Into<String>,
        value: crate::algebra::Vector,
    ) -> Step {
        Step {
            title: title.into(),
            table: None,
            vectors: vec![VectorRelation {
                name: name.into(),
                value,
            }],
            relations: Vec::new(),
        }
    }

    /// The step as it is shown: every relation [`Relation::simplified`], every table cell
    /// in its shortest form.
    pub fn simplified(&self, domains: &Domains) -> Step {
        Step {
            title: self.title.clone(),
            table: self.table.as_ref().map(|t| Table {
                columns: t.columns.clone(),
                rows: t
                    .rows
                    .iter()
                    .map(|row| TableRow {
                        label: row.label.clone(),
                        cells: row.cells.iter().map(|c| presented(c, domains)).collect(),
                    })
                    .collect(),
            }),
            vectors: self
                .vectors
                .iter()
                .map(|v| VectorRelation {
                    name: v.name.clone(),
                    value: v.value.map(|c| presented(&c, domains)),
                })
                .collect(),
            relations: self
                .relations
                .iter()
                .map(|r| r.simplified(domains))
                .collect(),
        }
    }
}

/// A named derivation and its steps; the last step holds the result.
#[derive(Debug, Clone, PartialEq)]
pub struct Derivation {
    /// Short machine name: `H_G`, `T`, `euler`, ...
    pub name: String,
    /// What is derived, in words.
    pub title: String,
    pub steps: Vec<Step>,
}

impl Derivation {
    /// The derivation as it is shown: every step [`Step::simplified`].
    pub fn simplified(&self, domains: &Domains) -> Derivation {
        Derivation {
            name: self.name.clone(),
            title: self.title.clone(),
            steps: self.steps.iter().map(|s| s.simplified(domains)).collect(),
        }
    }

    /// The relations of the final step.
    pub fn result(&self) -> &[Relation] {
        self.steps.last().map_or(&[], |s| s.relations.as_slice())
    }
}

#[cfg(test)]
mod tests {
    use super::presented;
    use crate::algebra::Domains;
    use crate::parse::parse_expression;

    fn expr(text: &str) -> crate::algebra::Expr {
        parse_expression("", text).unwrap()
    }

    #[test]
    fn a_fraction_inside_a_product_is_shown_over_one_denominator() {
        let domains = Domains::chapter_defaults();
        // H_y of Sample Problem 18.2, as the shortest form writes it.
        let nested = expr("-1/4*m*r*(4*L + r^2/L)*w_1");
        assert!(nested.has_nested_fraction());
        let shown = presented(&nested, &domains);
        assert!(!shown.has_nested_fraction(), "{shown}");
        let difference = (&shown - &nested).cancel().unwrap();
        assert!(difference.is_zero(), "{shown} is not {nested}");
        // A sum of fractions on its own is no nested fraction: shown as the shortest form.
        let flat = expr("W + m*r^3*w_1^2/(2*L^2)");
        assert!(!flat.has_nested_fraction());
        assert!(expr("1/(a + b/c)").has_nested_fraction());
    }
}
