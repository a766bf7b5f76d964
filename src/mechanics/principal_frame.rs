//! The principal moments and principal axes of a body about a point (G or O), with the
//! worked steps a textbook shows:
//!
//! ```text
//! det(λ1 − [I]) = 0                       the characteristic equation, [I] in the chapter's
//!                                          convention (off-diagonal −I_xy, −I_yz, −I_xz)
//! I_1 <= I_2 <= I_3                       its three roots, ascending
//! ([I] − I_k 1){e_k} = 0, |e_k| = 1       each principal axis
//! e_1 × e_2 = e_3                         a right-handed frame (det [e_1 e_2 e_3] = +1)
//! ```
//!
//! Exact where the answer is exact and decidable:
//! - every product of inertia zero: the roots are the moments themselves and the axes the
//!   frame's, their order proved from the symbols' domains or read from the givens' values;
//! - one product `I_ab` coupling two axes a, b (the third axis c principal):
//!   `I = (I_a + I_b)/2 ± √(((I_a − I_b)/2)² + I_ab²)` and `I_c`, the pair's axes
//!   `(I_ab e_a + (I_a − I) e_b)/√(I_ab² + (I_a − I)²)`, the order of `I_c` among them proved
//!   or read from the values.
//!
//! Otherwise the tensor is evaluated with the givens' values and solved numerically by
//! [`principal_axes`] (robust for near-equal moments); without values the error names the
//! givens that need one. Equal moments are said so: every axis in their plane is principal.

use super::derivation::{Derivation, Relation, Step};
use super::exact_principal::{rational_frame, ExactMatrix};
use super::inertia::InertiaTensor;
use super::principal_axes::principal_axes;
use super::validation::PhysicsError;
use crate::algebra::vector_products::{cross, dot};
use crate::algebra::{
    four_significant_figures, vector, AlgebraError, Axis, Domains, Expr, Matrix, Symbol, Vector, Q,
};
use nalgebra::Matrix3;
use num_rational::BigRational;
use std::cmp::Ordering;

/// Principal moments, ascending, and principal axes forming a right-handed orthonormal
/// frame: `[I] = Σ I_k e_k e_kᵀ`.
#[derive(Debug, Clone, PartialEq)]
pub struct PrincipalFrame {
    /// `I_1 <= I_2 <= I_3`.
    pub moments: [Expr; 3],
    /// `e_1, e_2, e_3`, unit vectors in the frame's axes, `e_1 × e_2 = e_3`.
    pub axes: [Vector; 3],
    /// Equal moments in words (title markup): which axes are any in their plane.
    pub remark: Option<String>,
}

/// Why the principal frame could not be found.
#[derive(Debug, Clone, PartialEq)]
pub enum PrincipalError {
    /// The moments' order (or a numeric solution) needs the values of these symbols.
    NeedsValues(Vec<Symbol>),
    /// The tensor with the givens' values is not a real body's.
    Physics(PhysicsError),
    Algebra(AlgebraError),
}

impl From<AlgebraError> for PrincipalError {
    fn from(e: AlgebraError) -> PrincipalError {
        PrincipalError::Algebra(e)
    }
}

/// Two moments compared by their values (`compare`) are one when they differ by no more
/// than this many roundings of the larger: each is a short expression in the givens' values.
const COMPARED_ROUNDINGS: f64 = 64.0;

/// The principal frame of `tensor` about `point` (`G`, `O`), with its steps. `values` gives
/// the givens' values (SI) where the scene has them.
///
/// A rectangular plate a × b in the xy plane about its centre: `I_x = m b²/12`,
/// `I_y = m a²/12`, `I_z = m(a² + b²)/12`; with a = 0.4 m, b = 0.3 m the order is
/// `I_x < I_y < I_z`, read from the values.
///
/// ```
/// use kinetics::mechanics::principal_frame::principal_frame;
/// use kinetics::algebra::{Domains, Symbol};
/// use kinetics::{parse_expression, InertiaTensor};
///
/// let hand = |t: &str| parse_expression("by hand", t).unwrap().expand().unwrap();
/// let plate = InertiaTensor::diagonal(["m b^2/12", "m a^2/12", "m (a^2 + b^2)/12"].map(hand));
/// let values = |s: Symbol| match s.name() { "a" => Some(0.4), "b" => Some(0.3), "m" => Some(2.0), _ => None };
/// let (frame, _) = principal_frame(&plate, "G", &Domains::chapter_defaults(), &values).unwrap();
/// assert_eq!(frame.moments, ["m b^2/12", "m a^2/12", "m (a^2 + b^2)/12"].map(hand));
/// assert!(frame.remark.is_none());
/// ```
pub fn principal_frame(
    tensor: &InertiaTensor,
    point: &str,
    domains: &Domains,
    values: &dyn Fn(Symbol) -> Option<f64>,
) -> Result<(PrincipalFrame, Derivation), PrincipalError> {
    let coupled: Vec<usize> = (0..3).filter(|&k| !tensor.products[k].is_zero()).collect();
    let (frame, how) = match coupled.as_slice() {
        [] => {
            let pairs = [0, 1, 2].map(|k| (tensor.moments[k].clone(), unit(k)));
            exact_frame(pairs, domains, values)?
        }
        [product] => {
            let pairs = one_product_pairs(tensor, *product)?;
            exact_frame(short_axes_or_numbers(pairs, values)?, domains, values)?
        }
        _ => (numeric_frame(tensor, values)?, Decided::Numerically),
    };
    let characteristic = characteristic_step(&coupled, point);
    let steps = vec![characteristic, frame_step(&frame, how, point)];
    Ok((
        frame,
        Derivation {
            name: format!("principal_{point}"),
            title: format!("principal moments and axes about {point}"),
            steps,
        },
    ))
}

/// How the order of the moments was decided.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Decided {
    Proved,
    ByValues,
    Numerically,
}

fn unit(k: usize) -> Vector {
    Vector::from_fn(|r, _| Expr::from(i64::from(r == k)))
}

/// The step `det(λ1 − [I]) = 0` in the names `I_x`, `I_xy`, … of the step that gives the
/// tensor: factored when at most one product couples two axes
/// (`(λ − I_c)((λ − I_a)(λ − I_b) − I_ab²)`), else by cofactors along the first row.
fn characteristic_step(coupled: &[usize], point: &str) -> Step {
    let lambda = Expr::symbol("lambda");
    // In the names of the step before (`I_x`, `I_xy`): short, and the reader has their values.
    let named = InertiaTensor::general();
    let root = |k: usize| &lambda - &named.moments[k];
    let (lhs, rhs) = match coupled {
        [] => (root(0) * root(1) * root(2), Expr::zero()),
        [product] => {
            let (a, b, c) = AXES_OF_PRODUCT[*product];
            let det = root(c) * (root(a) * root(b) - named.products[*product].powi(2));
            (det, Expr::zero())
        }
        // Each minor as written (multiplied out with the givens' values it ran past the
        // margin), the first cofactor equal to the other two: a right-hand side that breaks.
        _ => cofactors(&(Matrix::from_diagonal_element(lambda.clone()) - named.matrix())),
    };
    Step::new(
        format!(
            r"principal moments about ${point}$: the roots $\lambda$ of the characteristic equation $\mathrm{{det}}(\lambda 1 - [I]) = 0$"
        ),
        vec![Relation::new(lhs, rhs, Axis::X)],
    )
}

/// The axes a product couples and the third one, for `[I_xy, I_yz, I_xz]`.
const AXES_OF_PRODUCT: [(usize, usize, usize); 3] = [(0, 1, 2), (1, 2, 0), (0, 2, 1)];

/// `det M = 0` by cofactors along the first row, as `M₀₀ m₀₀ = M₀₁ m₀₁ − M₀₂ m₀₂` (each
/// `m` the minor of its entry).
fn cofactors(m: &Matrix) -> (Expr, Expr) {
    let minor = |r1: usize, r2: usize, c1: usize, c2: usize| {
        &m[(r1, c1)] * &m[(r2, c2)] - &m[(r1, c2)] * &m[(r2, c1)]
    };
    (
        &m[(0, 0)] * &minor(1, 2, 1, 2),
        &m[(0, 1)] * &minor(1, 2, 0, 2) - &m[(0, 2)] * &minor(1, 2, 0, 1),
    )
}

/// The symbols of `e` without a value (π, a constant, has one: `rpm` and `deg` bring it).
fn missing_values(e: &Expr, values: &dyn Fn(Symbol) -> Option<f64>) -> Vec<Symbol> {
    e.symbols()
        .into_iter()
        .filter(|s| s.name() != "lambda" && !s.is_pi() && values(*s).is_none())
        .collect()
}

/// A given's value as the exact decimal it reads as (`0.1` is 1/10).
fn exact(x: f64) -> Option<Expr> {
    let q = Q::parse_decimal(&format!("{:e}", x.abs()))?;
    Some(Expr::num(if x < 0.0 { -&q } else { q }))
}

/// One product `I_ab` coupling axes a and b (`product` indexes `[I_xy, I_yz, I_xz]`): the
/// pair `(I_a + I_b)/2 ∓ √(((I_a − I_b)/2)² + I_ab²)` with their axes, and `I_c` with `e_c`.
fn one_product_pairs(
    tensor: &InertiaTensor,
    product: usize,
) -> Result<[(Expr, Vector); 3], AlgebraError> {
    let (a, b, c) = AXES_OF_PRODUCT[product];
    let (ia, ib, iab) = (
        &tensor.moments[a],
        &tensor.moments[b],
        &tensor.products[product],
    );
    let half = Expr::num(Q::new(1, 2).unwrap_or(Q::ONE));
    let mean = (ia + ib) * half.clone();
    let radius = ((ia - ib) * half.clone()).powi(2) + iab.powi(2);
    let radius = radius.expand()?.checked_pow(&half)?;
    let axis = |moment: &Expr| -> Result<Vector, AlgebraError> {
        // ([I] − I 1) e = 0 in the plane of a and b: (I_a − I) e_a − I_ab e_b = 0.
        let (along_a, along_b) = (iab.clone(), (ia - moment).expand()?);
        let length = (along_a.powi(2) + along_b.powi(2))
            .expand()?
            .checked_pow(&half)?;
        let mut e = Vector::from_element(Expr::zero());
        e[a] = along_a.checked_div(&length)?;
        e[b] = along_b.checked_div(&length)?;
        Ok(e)
    };
    let low = (&mean - &radius).expand()?;
    let high = (&mean + &radius).expand()?;
    Ok([
        (tensor.moments[c].clone(), unit(c)),
        (low.clone(), axis(&low)?),
        (high.clone(), axis(&high)?),
    ])
}

/// Nodes beyond which an exact axis is no help to a reader (the normalising root of a
/// composite body's moments runs to hundreds of terms); it is given by its numbers instead.
const MAX_AXIS_NODES: usize = 60;

/// The pairs with each axis exact when short, else its numbers with the givens' values (the
/// moments stay exact).
fn short_axes_or_numbers(
    pairs: [(Expr, Vector); 3],
    values: &dyn Fn(Symbol) -> Option<f64>,
) -> Result<[(Expr, Vector); 3], PrincipalError> {
    let long = |e: &Vector| e.iter().any(|c| c.node_count() > MAX_AXIS_NODES);
    if !pairs.iter().any(|(_, e)| long(e)) {
        return Ok(pairs);
    }
    let missing: Vec<Symbol> = (pairs.iter())
        .flat_map(|(_, e)| e.iter().flat_map(|c| missing_values(c, values)))
        .collect();
    if !missing.is_empty() {
        return Err(PrincipalError::NeedsValues(sorted(missing)));
    }
    let number = |c: &Expr| -> Result<Expr, PrincipalError> {
        Ok(exact(c.eval(values)?).unwrap_or_else(Expr::zero))
    };
    let mut numeric = pairs.clone();
    for (k, (_, e)) in pairs.iter().enumerate() {
        let components = e.iter().map(number).collect::<Result<Vec<_>, _>>()?;
        numeric[k].1 = Vector::from_iterator(components);
    }
    Ok(numeric)
}

/// Exact moments and axes, ascending: the order proved from the domains, else read from the
/// givens' values (then `ByValues`), else the givens that need values.
fn exact_frame(
    mut pairs: [(Expr, Vector); 3],
    domains: &Domains,
    values: &dyn Fn(Symbol) -> Option<f64>,
) -> Result<(PrincipalFrame, Decided), PrincipalError> {
    let mut how = Decided::Proved;
    let mut equal = [false; 2];
    // Insertion sort of three: at most three comparisons, each decided or refused.
    for k in 1..3 {
        let mut j = k;
        while j > 0 {
            let (order, decided) = compare(&pairs[j - 1].0, &pairs[j].0, domains, values)?;
            if decided == Decided::ByValues {
                how = Decided::ByValues;
            }
            if order != Ordering::Greater {
                break;
            }
            pairs.swap(j - 1, j);
            j -= 1;
        }
    }
    for (k, same) in equal.iter_mut().enumerate() {
        *same = compare(&pairs[k].0, &pairs[k + 1].0, domains, values)?.0 == Ordering::Equal;
    }
    let [(m1, e1), (m2, e2), (m3, e3)] = pairs;
    // A coordinate axis keeps its form, its sense decided; any other third axis is e₁ × e₂,
    // right-handed by construction (`½ i − ½√3 j`, not a multiple of it with radicals).
    let e3 = if e3.iter().all(|c| c.as_num().is_some()) {
        proper_third([&e1, &e2, &e3], domains, values)?
    } else {
        vector::expand_each(&cross(&e1, &e2))?
    };
    Ok((
        PrincipalFrame {
            moments: [m1, m2, m3],
            axes: [e1, e2, e3],
            remark: equal_remark(equal),
        },
        how,
    ))
}

/// `e_3` or `−e_3`, whichever makes `e_1 × e_2 = e_3` (the axes are orthonormal, so the
/// triple product `e_1 × e_2 · e_3` is ±1): its sign a number, proved from the domains, or
/// read from the givens' values.
fn proper_third(
    [e1, e2, e3]: [&Vector; 3],
    domains: &Domains,
    values: &dyn Fn(Symbol) -> Option<f64>,
) -> Result<Vector, PrincipalError> {
    let triple = dot(&cross(e1, e2), e3).expand()?;
    let negative = match triple.as_num() {
        Some(q) => q.is_negative(),
        None if domains.is_positive(&triple) => false,
        None if domains.is_positive(&-&triple) => true,
        None => {
            let missing = missing_values(&triple, values);
            if !missing.is_empty() {
                return Err(PrincipalError::NeedsValues(sorted(missing)));
            }
            triple.eval(values)? < 0.0
        }
    };
    Ok(if negative { e3.map(|c| -c) } else { e3.clone() })
}

/// The order of two moments: proved from the domains (their difference's sign), else from
/// the givens' values: exactly when the difference is rational in the decimals written,
/// otherwise equal when the values differ by no more than rounding.
fn compare(
    a: &Expr,
    b: &Expr,
    domains: &Domains,
    values: &dyn Fn(Symbol) -> Option<f64>,
) -> Result<(Ordering, Decided), PrincipalError> {
    let difference = (b - a).expand()?;
    // Roots of squares of positive things come out (√(m²L⁴) = m L²): a zero is seen as one.
    let difference = difference.simplify(domains).unwrap_or(difference);
    if difference.is_zero() {
        return Ok((Ordering::Equal, Decided::Proved));
    }
    if domains.is_positive(&difference) {
        return Ok((Ordering::Less, Decided::Proved));
    }
    if domains.is_positive(&-&difference) {
        return Ok((Ordering::Greater, Decided::Proved));
    }
    let missing: Vec<Symbol> = [a, b]
        .iter()
        .flat_map(|e| missing_values(e, values))
        .collect();
    if !missing.is_empty() {
        return Err(PrincipalError::NeedsValues(sorted(missing)));
    }
    // With the decimals written, a rational difference is decided exactly.
    let decimal = |s: Symbol| values(s).and_then(exact);
    if let Some(q) = difference.subs(&decimal)?.as_num() {
        return Ok((Q::ZERO.cmp(q), Decided::ByValues));
    }
    let (x, y) = (a.eval(values)?, b.eval(values)?);
    let bound = COMPARED_ROUNDINGS * f64::EPSILON * x.abs().max(y.abs());
    let order = if (x - y).abs() <= bound {
        Ordering::Equal
    } else {
        x.total_cmp(&y)
    };
    Ok((order, Decided::ByValues))
}

fn sorted(mut symbols: Vec<Symbol>) -> Vec<Symbol> {
    symbols.sort_by(|a, b| a.name().cmp(b.name()));
    symbols.dedup();
    symbols
}

/// The frame of [`principal_axes`] on the tensor with the givens' values, each number the
/// exact decimal of the double found.
fn numeric_frame(
    tensor: &InertiaTensor,
    values: &dyn Fn(Symbol) -> Option<f64>,
) -> Result<PrincipalFrame, PrincipalError> {
    let matrix = tensor.matrix();
    let missing: Vec<Symbol> = matrix
        .iter()
        .flat_map(|e| missing_values(e, values))
        .collect();
    if !missing.is_empty() {
        return Err(PrincipalError::NeedsValues(sorted(missing)));
    }
    let entries = matrix
        .iter()
        .map(|e| e.eval(values))
        .collect::<Result<Vec<f64>, _>>()?;
    let entries = Matrix3::from_iterator(entries);
    let found = principal_axes(&entries).map_err(PrincipalError::Physics)?;
    let number = |x: f64| exact(x).unwrap_or_else(Expr::zero);
    let m = found.moments;
    let rational = exact_entries(&matrix, values)?;
    let frame = rational.and_then(|exact| rational_frame(&exact, [m[0], m[1], m[2]]));
    let (moments, axes, equal) = match frame {
        Some(frame) => (frame.moments, frame.axes, frame.equal),
        None => {
            let r = found.rotation.matrix();
            let bound = eigenvalue_rounding_bound(&matrix, &entries);
            (
                [m[0], m[1], m[2]],
                [0, 1, 2].map(|k| r.column(k).into_owned()),
                [0, 1].map(|k| m[k + 1] - m[k] <= bound),
            )
        }
    };
    Ok(PrincipalFrame {
        moments: moments.map(number),
        axes: axes.map(|e| Vector::from_fn(|row, _| number(e[row]))),
        remark: equal_remark(equal),
    })
}

/// The tensor's entries as exact rationals when the givens' values (the decimals written)
/// make every entry one; `None` when an entry is irrational (a root, a function).
fn exact_entries(
    matrix: &Matrix,
    values: &dyn Fn(Symbol) -> Option<f64>,
) -> Result<Option<ExactMatrix>, PrincipalError> {
    let decimal = |s: Symbol| values(s).and_then(exact);
    let mut out: ExactMatrix = Default::default();
    for row in 0..3 {
        for column in 0..3 {
            let entry = matrix[(row, column)].subs(&decimal)?;
            let Some(q) = entry.as_num() else {
                return Ok(None);
            };
            let (numerator, denominator) = q.parts();
            out[row][column] = BigRational::new(numerator, denominator);
        }
    }
    Ok(Some(out))
}

/// How far two computed moments of a tensor with irrational entries may be apart and still
/// be one: Weyl's bound on the eigenvalues' change, the rounding of each entry's evaluation
/// (about one rounding per operation written, of the entry's size) plus the eigenvalue
/// computation's own (a few roundings of the tensor's norm, nalgebra's symmetric
/// eigensolver being backward stable).
fn eigenvalue_rounding_bound(matrix: &Matrix, entries: &Matrix3<f64>) -> f64 {
    let evaluation: f64 = matrix
        .iter()
        .zip(entries.iter())
        .map(|(e, x)| (e.node_count() as f64) * f64::EPSILON * x.abs())
        .sum();
    evaluation + EIGENSOLVER_ROUNDINGS * f64::EPSILON * entries.norm()
}

/// Roundings of the tensor's norm the symmetric eigensolver may make (three sweeps of Jacobi
/// rotations on a 3 × 3 tensor, with room).
const EIGENSOLVER_ROUNDINGS: f64 = 32.0;

/// `I_1 = I_2`: the axes in the plane normal to `e_3` are all principal; and so on.
fn equal_remark(equal: [bool; 2]) -> Option<String> {
    Some(
        match equal {
            [true, true] => "$I_1 = I_2 = I_3$: every axis through the point is principal ($e_1$, $e_2$, $e_3$ are one choice)",
            [true, false] => "$I_1 = I_2$: every axis perpendicular to $e_3$ is principal ($e_1$, $e_2$ are one choice)",
            [false, true] => "$I_2 = I_3$: every axis perpendicular to $e_1$ is principal ($e_2$, $e_3$ are one choice)",
            [false, false] => return None,
        }
        .into(),
    )
}

/// The step that gives the moments and axes: a relation `I_k = …`, `e_k = …` for each exact
/// one; the numbers of those found numerically (four significant figures, SI) in the title.
fn frame_step(frame: &PrincipalFrame, how: Decided, point: &str) -> Step {
    let order = match how {
        Decided::Proved => "ascending",
        Decided::ByValues => "ascending with the givens' values",
        Decided::Numerically => "found numerically with the givens' values (SI)",
    };
    let mut title = format!(
        r"principal moments about ${point}$, {order}, and principal axes, the unit solutions of $([I] - I_k 1)\{{e_k\}} = 0$ with $e_1 \times e_2 = e_3$ (a right-handed frame)"
    );
    let mut relations = Vec::new();
    let mut numbers = Vec::new();
    let moments = frame
        .moments
        .iter()
        .map(|m| (m.clone(), "I", is_numeric(std::slice::from_ref(m))));
    let axes = frame
        .axes
        .iter()
        .map(|e| (vector_sum(e), "e", is_numeric(e.as_slice())));
    for (k, (value, name, numeric)) in moments.enumerate().chain(axes.enumerate()) {
        let name = format!("{name}_{}", k + 1);
        if !numeric {
            relations.push(Relation::new(Expr::symbol(&name), value, Axis::X));
        } else if name.starts_with('I') {
            numbers.push(format!("${name} = {}$", four_figures(&value)));
        } else {
            numbers.push(format!("${name} = {}$", numeric_axis(&frame.axes[k])));
        }
    }
    if !numbers.is_empty() {
        title.push_str(": ");
        title.push_str(&numbers.join(", "));
    }
    if let Some(remark) = &frame.remark {
        title.push_str("; ");
        title.push_str(remark);
    }
    Step::new(title, relations)
}

/// Whether these are numbers found numerically (the exact decimals of doubles, not an axis
/// such as `i` or `-k`): read by their four figures, not as fractions.
fn is_numeric(components: &[Expr]) -> bool {
    components.iter().all(|c| c.as_num().is_some())
        && components
            .iter()
            .any(|c| c.as_num().is_some_and(|q| !q.is_integer()))
}

/// `a i + b j + c k`.
fn vector_sum(v: &Vector) -> Expr {
    v.iter()
        .zip(vector::unit_vectors())
        .fold(Expr::zero(), |sum, (c, u)| sum + c * &u)
}

/// A numeric axis as the results show it, `0.8366\,\mathbf{i} - 0.496\,\mathbf{j}`: each
/// component that is not zero in four figures, times its unit vector.
fn numeric_axis(e: &Vector) -> String {
    let mut out = String::new();
    for (c, unit) in e.iter().zip(["i", "j", "k"]) {
        let shown = four_figures(c);
        let magnitude = shown.trim_start_matches('-');
        if magnitude == "0" {
            continue;
        }
        out.push_str(match (out.is_empty(), shown.starts_with('-')) {
            (true, false) => "",
            (true, true) => "-",
            (false, false) => " + ",
            (false, true) => " - ",
        });
        out.push_str(&format!(r"{magnitude}\,\mathbf{{{unit}}}"));
    }
    out
}

/// A number in four significant figures, as the results show it.
fn four_figures(e: &Expr) -> String {
    four_significant_figures(e.as_num().map_or(f64::NAN, Q::to_f64))
}
