//! An exact expression as a tree of Python tuples, which `kinetics._sympy` builds SymPy
//! from node by node (no text is parsed):
//!
//! | node | tuple |
//! |---|---|
//! | a rational p/q | `("number", "p", "q")` (decimal digits: any size) |
//! | a symbol | `("symbol", name, positive)`, `positive` from the scene's domains |
//! | π | `("pi",)` |
//! | a sum, a product | `("add", (terms…))`, `("mul", (factors…))` |
//! | a power | `("pow", base, exponent)` |
//! | sin cos tan abs acos atan | `("function", name, argument)` |

use kinetics::{Domain, Domains, Expr, View};
use pyo3::prelude::*;
use pyo3::types::PyTuple;

/// The tree of `e`, its symbols positive where `domains` says so.
pub fn tree<'py>(py: Python<'py>, e: &Expr, domains: &Domains) -> PyResult<Bound<'py, PyTuple>> {
    match e.view() {
        View::Num(q) => PyTuple::new(
            py,
            [
                "number".to_string(),
                q.numer().to_string(),
                q.denom().to_string(),
            ],
        ),
        View::Sym(s) if s.is_pi() => PyTuple::new(py, ["pi"]),
        View::Sym(s) => {
            let positive = domains.domain(s) == Domain::Positive;
            ("symbol", s.name(), positive).into_pyobject(py)
        }
        View::Add(terms) => ("add", operands(py, terms, domains)?).into_pyobject(py),
        View::Mul(factors) => ("mul", operands(py, factors, domains)?).into_pyobject(py),
        View::Pow(base, exponent) => (
            "pow",
            tree(py, base, domains)?,
            tree(py, exponent, domains)?,
        )
            .into_pyobject(py),
        View::Func(f, argument) => {
            ("function", f.name(), tree(py, argument, domains)?).into_pyobject(py)
        }
    }
}

/// The trees of a sum's terms or a product's factors.
fn operands<'py>(
    py: Python<'py>,
    operands: &[Expr],
    domains: &Domains,
) -> PyResult<Bound<'py, PyTuple>> {
    let trees = operands
        .iter()
        .map(|e| tree(py, e, domains))
        .collect::<PyResult<Vec<_>>>()?;
    PyTuple::new(py, trees)
}
