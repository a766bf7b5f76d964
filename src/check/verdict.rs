//! The verdict on a claim: `holds`, `differs` or `undecided`, never a guess.
//!
//! Each component (a scalar claim has one, a vector claim three) is decided twice:
//! exactly, by the algebra — `correct − claimed` over one denominator with its numerator
//! multiplied out, then `sin² + cos² = 1`, the double angles and the shortest form — and by a
//! second opinion, both sides evaluated in double-double at random points
//! ([`second_opinion`]). The claim holds when both find the difference zero, differs when
//! both find it not zero; any disagreement, or an algebra beyond its bounds with no
//! numerical counterexample, is `undecided`.
//!
//! The side taken as correct is the one that names a derived quantity (`T`, `H_O`): its
//! value is the derivation's. Without one (pure algebra, `(w1 i + w2 j) × (L i − r j) = ...`)
//! the left side is computed and the right side is the claim. An equation that is a nonzero
//! multiple of the correct one (`2T = ...`) holds: the derived value stands in it.

use super::context::Context;
use super::diagnosis::{diagnose, Diagnosis};
use super::dimension::{odd_term_in, OddTerm};
use super::second_opinion::{second_opinion, Opinion};
use crate::algebra::vector::{components, has_unit_vectors};
use crate::algebra::{AlgebraError, Axis, Domains, Expr, Vector};
use crate::algebra::{Role, Symbol};
use crate::mechanics::slip::Slip;
use crate::parse::claim::{Claim, ClaimSide};
use crate::parse::Diagnostic;
use crate::parse::{ClaimSyntax, Follows};
use crate::scene::named_unit::NamedUnit;
use crate::scene::units::{dimension_with, Dimension};
use crate::scene::units_in_math::{in_system, marker_dimension};

/// What a check concludes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Verdict {
    Holds,
    Differs,
    Undecided,
}

/// One component of a claim (the only one of a scalar claim) and its verdict.
#[derive(Debug, Clone)]
pub struct Component {
    /// The axis of a vector claim's component; `None` for a scalar claim.
    pub axis: Option<Axis>,
    /// The value of the side taken as correct.
    pub correct: Expr,
    /// The value of the other side, as claimed.
    pub claimed: Expr,
    pub verdict: Verdict,
    /// Why the verdict is `undecided`, in words.
    pub undecided_because: Option<String>,
    /// What differs, term by term, when the verdict is `differs`.
    pub diagnosis: Option<Diagnosis>,
    /// A component written in numbers: both values, decided within the tolerance.
    pub numbers: Option<Numbers>,
    /// The values before the givens' values were put in (the same as `correct` and
    /// `claimed` for a claim in the givens' names).
    pub correct_in_symbols: Expr,
    pub claimed_in_symbols: Expr,
}

/// A slip that explains a claim: in the context derived with it the claim holds.
#[derive(Debug, Clone)]
pub struct SlipReading {
    pub slip: Slip,
    /// What the slipped piece is worth in each component that differs.
    pub pieces: Vec<Piece>,
}

/// The part of one component the slip changed: correct − slipped, in the givens' names,
/// and its value when the claim is in numbers.
#[derive(Debug, Clone)]
pub struct Piece {
    pub axis: Option<Axis>,
    pub in_symbols: Expr,
    pub value: Option<f64>,
}

/// A component written in numbers (`T_BC = 1857 N`), decided by its values within the
/// context's relative tolerance: `|claimed − correct| ≤ rtol · |correct|`.
#[derive(Debug, Clone, PartialEq)]
pub struct Numbers {
    pub correct: f64,
    pub claimed: f64,
    /// `|claimed − correct| / |correct|` (infinite when the correct value is zero and the
    /// claimed one is not).
    pub relative: f64,
    pub tolerance: f64,
    /// The unit of the numbers: the scene's unit system's for the component's dimension
    /// (none when the dimension cannot be told or is a pure number).
    pub unit: Option<NamedUnit>,
}

/// The check of one claim.
#[derive(Debug, Clone)]
pub struct Report {
    /// The claim as written.
    pub claim: String,
    /// The text of the side taken as correct, and of the claimed side.
    pub correct_side: String,
    pub claimed_side: String,
    /// Whether the correct side names a derived quantity (`T`, `2 H_x`); else it is the left
    /// side of a claim of pure algebra, computed.
    pub correct_is_derived: bool,
    pub verdict: Verdict,
    /// The components checked (both sides zero are left out of a vector claim).
    pub components: Vec<Component>,
    /// A term whose dimension differs from the others': the claim is not checked further.
    pub odd_term: Option<OddTerm>,
    /// The slip of the mechanics that turns the correct side into the claimed one.
    pub slip: Option<SlipReading>,
    /// The solution of the scene's equations the claim is decided in (from 0), of
    /// `solutions` (1 unless a name it uses has a value in each of several).
    pub solution: usize,
    pub solutions: usize,
}

impl Report {
    /// The slip in words: the mechanics' slip's concept, or the first differing
    /// component's reading's explanation, or the odd term's dimension.
    pub fn reading_words(&self) -> Option<String> {
        if let Some(odd) = &self.odd_term {
            return Some(format!("the term {} {}", odd.text, odd.reason));
        }
        if let Some(slip) = &self.slip {
            return Some(crate::print::markup::text(slip.slip.concept()));
        }
        self.components
            .iter()
            .filter(|c| c.verdict == Verdict::Differs)
            .find_map(|c| Some(c.diagnosis.as_ref()?.reading.as_ref()?.explanation.clone()))
    }

    /// The name of the slip: `inhomogeneous`, or the first differing component's reading.
    pub fn reading(&self) -> Option<&'static str> {
        if self.odd_term.is_some() {
            return Some(super::dimension::INHOMOGENEOUS);
        }
        if let Some(slip) = &self.slip {
            return Some(slip.slip.name());
        }
        self.components
            .iter()
            .filter(|c| c.verdict == Verdict::Differs)
            .find_map(|c| c.diagnosis.as_ref()?.reading.as_ref().map(|r| r.name))
    }
}

/// Checks the claim `text` in `context`. A claim that cannot be read (a syntax error, an
/// unknown name, no `=`, a vector equated to a scalar) is a located error. A claim about a
/// quantity with a value in each solution of a scene's equations holds when it holds in
/// one of them (the top's slow or fast precession), and says which.
pub fn check(context: &Context, source_name: &str, text: &str) -> Result<Report, Diagnostic> {
    check_parsed(context, &ClaimSyntax::parse(source_name, text)?)
}

/// [`check`] of a claim already parsed (a derivation's line, checked again in the world of
/// the earlier lines, is parsed once).
pub fn check_parsed(context: &Context, syntax: &ClaimSyntax) -> Result<Report, Diagnostic> {
    let first = check_in_solution(context, syntax, 0)?;
    if first.verdict == Verdict::Holds {
        return Ok(first);
    }
    for k in 1..first.solutions {
        let report = check_in_solution(context, syntax, k)?;
        if report.verdict == Verdict::Holds {
            return Ok(report);
        }
    }
    Ok(first)
}

/// [`check`] with each name in the solution `k` of the scene's equations.
fn check_in_solution(
    context: &Context,
    syntax: &ClaimSyntax,
    k: usize,
) -> Result<Report, Diagnostic> {
    let (source_name, text) = (syntax.source_name(), syntax.text());
    let (claim, wrote_unit) = read(context, syntax, k)?;
    let solutions = claim
        .resolved_names()
        .map(|n| context.solution_count(n))
        .max()
        .unwrap_or(1);
    let (correct, claimed) = sides(context, &claim);
    let side_text = |side: &ClaimSide| text[side.span.0..side.span.1].to_string();
    let mut report = Report {
        claim: text.to_string(),
        correct_side: side_text(correct),
        claimed_side: side_text(claimed),
        correct_is_derived: is_derived(context, correct),
        verdict: Verdict::Differs,
        components: Vec::new(),
        odd_term: odd_term_in(
            &claim,
            text,
            &|s| context.dimension(s),
            context.unit_system(),
        ),
        slip: None,
        solution: k,
        solutions,
    };
    if !context.is_world()
        && report.odd_term.as_ref().is_some_and(|odd| {
            !written_in_plain_numbers(context, &claim, text, wrote_unit, odd.span)
        })
    {
        return Ok(report);
    }
    report.odd_term = None;
    let seed = seed_of(text);
    report.components = compared(context, &claim, source_name, text)?
        .into_iter()
        .map(|mut pair| match pair.numbers.take() {
            Some(numbers) => numeric_component(pair, numbers),
            None => in_symbols_where_it_differs(pair, context.domains(), seed),
        })
        .collect();
    report.verdict = overall(&report.components);
    if report.verdict == Verdict::Differs {
        report.slip = slip_reading(context, &claim, syntax, &report);
    }
    Ok(report)
}

/// The claim read in `context` (its names resolved, a unit after a number as its marker),
/// and whether it writes a unit (`1857 N`).
fn read(
    context: &Context,
    syntax: &ClaimSyntax,
    solution: usize,
) -> Result<(Claim, bool), Diagnostic> {
    let wrote_unit = std::cell::Cell::new(false);
    let unit = |name: &str, follows: Follows| {
        let unit = context.unit(name, follows);
        wrote_unit.set(wrote_unit.get() || unit.is_some());
        unit
    };
    let resolve = |name: &str| context.name_in_solution(name, solution);
    let claim = syntax.read(&resolve, Some(&unit))?;
    Ok((claim, wrote_unit.get()))
}

/// Whether a side names a derived quantity (not only aliases of symbols).
fn is_derived(context: &Context, side: &ClaimSide) -> bool {
    side.resolved.iter().any(|n| !context.is_alias(n))
}

/// `(correct, claimed)`: the side that names a derived quantity is correct; else the left.
fn sides<'c>(context: &Context, claim: &'c Claim) -> (&'c ClaimSide, &'c ClaimSide) {
    if is_derived(context, &claim.rhs) && !is_derived(context, &claim.lhs) {
        (&claim.rhs, &claim.lhs)
    } else {
        (&claim.lhs, &claim.rhs)
    }
}

/// One component's two sides as they are compared: in the scene's units, and at the givens' values when
/// the claim is written with them (then in numbers when nothing else is left).
struct Compared {
    axis: Option<Axis>,
    correct: Expr,
    claimed: Expr,
    /// The sides before the givens' values were put in.
    correct_in_symbols: Expr,
    claimed_in_symbols: Expr,
    numbers: Option<Numbers>,
}

/// The names of kinetic energies, whose unit is work's (ft·lb, J).
const KINETIC_ENERGIES: [&str; 6] = ["T", "T_1", "T_2", "T_lost", "T_trans", "T_rot"];

/// The components of a claim as they are compared ([`Compared`]).
fn compared(
    context: &Context,
    claim: &Claim,
    source_name: &str,
    text: &str,
) -> Result<Vec<Compared>, Diagnostic> {
    let (correct, claimed) = sides(context, claim);
    let energy = correct
        .resolved
        .iter()
        .any(|n| KINETIC_ENERGIES.contains(&n.as_str()));
    let algebra_error = |e: AlgebraError| {
        Diagnostic::at(source_name, text, 0, text.len(), e.to_string())
            .with_help("the claim is beyond the bounds of the algebra; write it in parts")
    };
    Ok(pairs(claim, correct, claimed)
        .map_err(algebra_error)?
        .into_iter()
        .map(|(axis, c, s)| {
            // The unit from the correct side as marked (`context.rs`, `in_dimension`): its
            // hidden lengths made up; a kinetic energy's is work (ft·lb, J).
            let marked = |s: Symbol| context.dimension(s).or_else(|| marker_dimension(s));
            let unit = dimension_with(&c, &marked)
                .ok()
                .filter(|d| *d != Dimension::NONE)
                .map(|d| context.unit_system().unit(d, energy));
            // A number written with its unit (`T_BC - 2700 N`), or a decimal where the givens
            // have values (`T_BC - 1/2*20*2.4*cos(beta)*15^2`), is a quantity in numbers: the
            // claim is decided at the givens' values, whatever names it also holds.
            let with_units = s.has_symbol_where(&|sym| marker_dimension(sym).is_some())
                || context.has_values() && holds_decimal(text);
            let in_units = |e: Expr| in_system(&e, context.unit_system()).unwrap_or(e);
            let (c, s) = (in_units(c), in_units(s));
            if !with_units && !evaluated_givens(context, &c, &s) {
                return Compared {
                    axis,
                    correct_in_symbols: c.clone(),
                    claimed_in_symbols: s.clone(),
                    correct: c,
                    claimed: s,
                    numbers: None,
                };
            }
            let (values_c, values_s) = (in_values(context, &c), in_values(context, &s));
            // A claimed side that still names quantities and holds no decimal and no unit
            // (`1/4 m r^2 w_1^2` where T also holds w_2) is exact: decided at the values
            // exactly, never within the tolerance of a number read off a calculator.
            let exact = !with_units && !holds_decimal(text) && s.has_symbol_where(&|t| !t.is_pi());
            let numbers = in_numbers(&values_c, &values_s)
                .filter(|_| !exact)
                .map(|values| Numbers::new(values, context.relative_tolerance(), unit));
            Compared {
                axis,
                correct: values_c,
                claimed: values_s,
                correct_in_symbols: c,
                claimed_in_symbols: s,
                numbers,
            }
        })
        .collect())
}

/// The claim's components in `context` when it holds there, decided quickly: each
/// component in numbers within the tolerance, or else by evaluation alone (25 digits at
/// random points). For trying a slip's context, where the verdict is already `differs` and
/// only its reading is sought.
fn holding_by_values(
    context: &Context,
    syntax: &ClaimSyntax,
    solution: usize,
) -> Option<Vec<Compared>> {
    let (source_name, text) = (syntax.source_name(), syntax.text());
    let (claim, _) = read(context, syntax, solution).ok()?;
    let compared = compared(context, &claim, source_name, text).ok()?;
    let seed = seed_of(text);
    let holds = compared.iter().all(|pair| match &pair.numbers {
        Some(numbers) => numbers.holds(),
        None => matches!(
            second_opinion(&pair.correct, &pair.claimed, context.domains(), seed),
            Opinion::Zero
        ),
    });
    holds.then_some(compared)
}

/// The first slip of [`Slip::ALL`] in whose context the claim holds, with what the slipped
/// piece is worth in each component that differs.
fn slip_reading(
    context: &Context,
    claim: &Claim,
    syntax: &ClaimSyntax,
    report: &Report,
) -> Option<SlipReading> {
    Slip::ALL.into_iter().find_map(|slip| {
        if !claim
            .resolved_names()
            .any(|name| context.slip_changes(slip, name))
        {
            return None;
        }
        let slipped = context.slipped(slip)?;
        let as_slipped = holding_by_values(slipped, syntax, report.solution)?;
        // A claim whose claimed side names what the slip changes, and whose every side the
        // slip makes zero (`Hdot_z = I_xz alpha - I_xy w^2` with the products of inertia
        // dropped), holds there vacuously: it is not explained (`B_y = 0` is).
        let (_, claimed) = sides(context, claim);
        let claimed_slips = claimed
            .resolved
            .iter()
            .any(|name| context.slip_changes(slip, name));
        if claimed_slips
            && as_slipped
                .iter()
                .all(|c| c.correct.is_zero() && c.claimed.is_zero())
        {
            return None;
        }
        let pieces = report
            .components
            .iter()
            .filter(|c| c.verdict == Verdict::Differs)
            .map(|c| {
                let in_symbols = match as_slipped.iter().find(|s| s.axis == c.axis) {
                    Some(s) => &c.correct_in_symbols - &s.correct_in_symbols,
                    None => c.correct_in_symbols.clone(),
                };
                // Its value, where the givens have values.
                let value = in_values(context, &in_symbols).eval::<f64>(&|_| None).ok();
                Piece {
                    axis: c.axis,
                    in_symbols,
                    value,
                }
            })
            .collect();
        Some(SlipReading { slip, pieces })
    })
}

/// Both sides' values, when neither holds a symbol (π aside): a claim written in numbers;
/// and the scale of the correct side ([`value_and_scale`]).
fn in_numbers(correct: &Expr, claimed: &Expr) -> Option<(f64, f64, f64)> {
    let (value, scale) = value_and_scale(correct, &plain_value)?;
    Some((value, plain_value(claimed)?, scale))
}

/// The value of `e` when it holds no symbol (π aside) and is finite.
pub(in crate::check) fn plain_value(e: &Expr) -> Option<f64> {
    if e.has_symbol_where(&|s| !s.is_pi()) {
        return None;
    }
    e.eval::<f64>(&|_| None).ok().filter(|v| v.is_finite())
}

/// `e`'s value and its scale, the sum of its terms' magnitudes, each term valued by `value`
/// (an exact zero evaluates to round-off of that size: `3 r cos θ φ̇² − 2 r ψ̇ φ̇ + 4 g = 0`
/// at a root); none when a term has no value.
pub(in crate::check) fn value_and_scale(
    e: &Expr,
    value: &dyn Fn(&Expr) -> Option<f64>,
) -> Option<(f64, f64)> {
    let scale = e
        .terms()
        .iter()
        .map(|t| value(t).map(f64::abs))
        .sum::<Option<f64>>()?;
    Some((value(e)?, scale))
}

/// A difference this small relative to the scale of the correct side's terms is round-off.
const ROUND_OFF: f64 = 1e-12;

impl Numbers {
    fn new(
        (correct, claimed, scale): (f64, f64, f64),
        tolerance: f64,
        unit: Option<NamedUnit>,
    ) -> Numbers {
        let off = (claimed - correct).abs();
        let relative = if off <= ROUND_OFF * scale.max(claimed.abs()) {
            0.0
        } else {
            off / correct.abs()
        };
        Numbers {
            correct,
            claimed,
            relative,
            tolerance,
            unit,
        }
    }

    /// Whether the claimed number is within the tolerance of the correct one.
    pub fn holds(&self) -> bool {
        self.relative <= self.tolerance
    }
}

/// A component written in numbers, decided by its values alone ([`Numbers`]).
/// One that differs, written in symbols that leave a given out (`A_x = -1/6 m L w^2 cos(beta)`
/// without g), is diagnosed term by term in the givens' names.
fn numeric_component(pair: Compared, numbers: Numbers) -> Component {
    let verdict = match numbers.holds() {
        true => Verdict::Holds,
        false => Verdict::Differs,
    };
    let in_symbols = pair.claimed_in_symbols.has_symbol_where(&|s| !s.is_pi());
    let diagnosis = match verdict {
        Verdict::Differs if in_symbols => {
            diagnose(&pair.claimed_in_symbols, &pair.correct_in_symbols).ok()
        }
        _ => None,
    };
    Component {
        axis: pair.axis,
        correct: pair.correct,
        claimed: pair.claimed,
        verdict,
        undecided_because: None,
        diagnosis,
        numbers: Some(numbers),
        correct_in_symbols: pair.correct_in_symbols,
        claimed_in_symbols: pair.claimed_in_symbols,
    }
}

/// Whether the claimed side was written with a given's value in place of its name: the
/// correct side holds a given that has a value, and the claimed side does not hold it
/// (`cos(beta) = 1/2` with `beta = 60 deg`, `A_y = 196.2`). Such a claim is decided at the
/// givens' exact values; a claim in the givens' names is decided in their names.
fn evaluated_givens(context: &Context, correct: &Expr, claimed: &Expr) -> bool {
    correct
        .symbols()
        .into_iter()
        .any(|s| context.value(s).is_some() && !claimed.contains(s))
}

/// `e` with every given that has a value replaced by it (exact, in the scene's units).
fn in_values(context: &Context, e: &Expr) -> Expr {
    e.subs(&|s| context.value(s)).unwrap_or_else(|_| e.clone())
}

/// Whether the dimension check passes over the odd term at `span`, because the claim is
/// written in plain numbers (the scene's units) in a scene whose givens have values: the term is a plain number
/// (`A_y = 196.2`, not a term without a unit), or the claim holds a decimal number and no
/// unit, and the number may stand for a quantity in the scene's units (`0.3 B_y` with 0.3 the 300 mm arm).
/// Such a claim is decided by its values.
fn written_in_plain_numbers(
    context: &Context,
    claim: &Claim,
    text: &str,
    wrote_unit: bool,
    span: (usize, usize),
) -> bool {
    let plain_number = || {
        claim
            .lhs
            .terms
            .iter()
            .chain(&claim.rhs.terms)
            .find(|t| t.span == span)
            .is_some_and(|t| !t.value.has_symbol_where(&|s| !is_number_symbol(context, s)))
    };
    context.has_values() && (plain_number() || holds_decimal(text) && !wrote_unit)
}

/// Whether `text` writes a decimal number (`0.3`, `.5`, `2.`).
fn holds_decimal(text: &str) -> bool {
    let bytes = text.as_bytes();
    bytes.iter().enumerate().any(|(k, b)| {
        let digit_at =
            |i: Option<usize>| i.and_then(|i| bytes.get(i)).is_some_and(u8::is_ascii_digit);
        *b == b'.' && (digit_at(k.checked_sub(1)) || digit_at(Some(k + 1)))
    })
}

/// The symbols a number may hold: π, the unit vectors of a vector in numbers, and the
/// angles (no unit) left in names (`-π cos θ / 2` for ψ̇ with φ̇ = π rad/s).
fn is_number_symbol(context: &Context, s: Symbol) -> bool {
    s.is_pi() || s.role() == Role::UnitVector || context.dimension(s) == Some(Dimension::NONE)
}

/// The components to compare, `(axis, correct, claimed)`: one for scalars, and for vectors
/// the three axes without those where both sides are zero.
fn pairs(
    claim: &Claim,
    correct: &ClaimSide,
    claimed: &ClaimSide,
) -> Result<Vec<(Option<Axis>, Expr, Expr)>, AlgebraError> {
    let is_vector = has_unit_vectors(&claim.lhs.value) || has_unit_vectors(&claim.rhs.value);
    if !is_vector {
        return Ok(vec![(None, correct.value.clone(), claimed.value.clone())]);
    }
    let as_vector = |e: &Expr| -> Result<Vector, AlgebraError> {
        if e.is_zero() {
            Ok(Vector::from_element(Expr::zero()))
        } else {
            components(e)
        }
    };
    let (c, s) = (as_vector(&correct.value)?, as_vector(&claimed.value)?);
    Ok([Axis::X, Axis::Y, Axis::Z]
        .into_iter()
        .enumerate()
        .filter(|&(k, _)| !(c[k].is_zero() && s[k].is_zero()))
        .map(|(k, axis)| (Some(axis), c[k].clone(), s[k].clone()))
        .collect())
}

/// The claim's verdict from its components': differs if one differs, else undecided if one
/// is, else holds.
fn overall(components: &[Component]) -> Verdict {
    let any = |v| components.iter().any(|c| c.verdict == v);
    if any(Verdict::Differs) {
        Verdict::Differs
    } else if any(Verdict::Undecided) {
        Verdict::Undecided
    } else {
        Verdict::Holds
    }
}

/// A component not in numbers. Decided as compared (at the givens' values where the claimed
/// side leaves a given out: it may have been written as its value); where that differs and
/// the values were put in, decided again in the givens' names and reported so: a claim that
/// left a term out (`Hdot_z = -I_xz alpha`, no ω) reads as `-3ML/(16c)` against
/// `-3ML/(16c) - ¼ m L c ω²`, not as fractions of the values times L.
fn in_symbols_where_it_differs(pair: Compared, domains: &Domains, seed: u64) -> Component {
    let substituted =
        pair.correct != pair.correct_in_symbols || pair.claimed != pair.claimed_in_symbols;
    let in_symbols = Compared {
        axis: pair.axis,
        correct: pair.correct_in_symbols.clone(),
        claimed: pair.claimed_in_symbols.clone(),
        correct_in_symbols: pair.correct_in_symbols.clone(),
        claimed_in_symbols: pair.claimed_in_symbols.clone(),
        numbers: None,
    };
    let decided = component(pair, domains, seed);
    if decided.verdict != Verdict::Differs || !substituted {
        return decided;
    }
    let again = component(in_symbols, domains, seed);
    match again.verdict {
        Verdict::Differs => again,
        _ => decided,
    }
}

/// What the exact route finds of `correct − claimed`.
enum Exact {
    Zero,
    Nonzero,
    Refused(AlgebraError),
}

/// One component decided by the algebra and by evaluation.
fn component(pair: Compared, domains: &Domains, seed: u64) -> Component {
    let Compared {
        axis,
        correct,
        claimed,
        correct_in_symbols,
        claimed_in_symbols,
        ..
    } = pair;
    // In single angles, so that `tan β = sin β / cos β`, `1 + tan² = sec²` and
    // `sin 2θ = 2 sin θ cos θ` reduce.
    let difference = match (correct.in_single_angles(), claimed.in_single_angles()) {
        (Ok(c), Ok(s)) => &c - &s,
        _ => &correct - &claimed,
    };
    let expanded = expanded_numerator(&difference);
    let opinion = second_opinion(&correct, &claimed, domains, seed);
    let exact = match (&expanded, &opinion) {
        (Ok(numerator), _) if numerator.is_zero() => Exact::Zero,
        // Multiplying out does not see trigonometric or radical identities: before saying
        // `differs` against an evaluation that finds no difference, reduce them.
        (Ok(numerator), Opinion::Zero | Opinion::Unsure(_)) => {
            match reduced_is_zero(numerator, &difference, domains) {
                Ok(true) => Exact::Zero,
                Ok(false) => Exact::Nonzero,
                Err(e) => Exact::Refused(e),
            }
        }
        (Ok(_), Opinion::Nonzero { .. }) => Exact::Nonzero,
        (Err(e), _) => Exact::Refused(e.clone()),
    };
    let (verdict, undecided_because) = match (&exact, &opinion) {
        (Exact::Zero, Opinion::Zero) => (Verdict::Holds, None),
        (Exact::Nonzero | Exact::Refused(_), Opinion::Nonzero { .. }) => (Verdict::Differs, None),
        (Exact::Zero, Opinion::Nonzero { relative, .. }) => (
            Verdict::Undecided,
            Some(format!(
                "the algebra finds the sides equal, but evaluation finds a relative \
                 difference of {relative:.1e}"
            )),
        ),
        (Exact::Nonzero, Opinion::Zero) => (
            Verdict::Undecided,
            Some(
                "the algebra cannot show the sides equal, but they agree to 25 digits at \
                 every point tried"
                    .into(),
            ),
        ),
        (Exact::Refused(e), Opinion::Zero) => (
            Verdict::Undecided,
            Some(format!(
                "the sides agree to 25 digits at every point tried, and the algebra \
                 could not decide: {e}"
            )),
        ),
        (_, Opinion::Unsure(why)) => (Verdict::Undecided, Some(why.clone())),
    };
    // A difference too large to multiply out is too large to read term by term.
    let diagnosis = match verdict {
        Verdict::Differs if expanded.is_ok() => diagnose(&claimed, &correct).ok(),
        _ => None,
    };
    Component {
        axis,
        claimed,
        verdict,
        undecided_because,
        diagnosis,
        numbers: None,
        correct_in_symbols,
        claimed_in_symbols,
        correct,
    }
}

/// The most terms (estimated before the work, [`Expr::estimated_expanded_terms`]) the exact route
/// multiplies a numerator out to: beyond, it would take seconds, and the second opinion
/// decides alone (`differs` on a clear difference, else `undecided`).
const EXPANDED_TERMS: usize = 20_000;

/// The numerator of `difference` over one denominator, multiplied out: zero exactly when the
/// sides are equal as rational functions.
fn expanded_numerator(difference: &Expr) -> Result<Expr, AlgebraError> {
    if difference.is_zero() {
        return Ok(Expr::zero());
    }
    let (numerator, _) = difference.together_parts()?;
    let size = numerator.estimated_expanded_terms();
    if size > EXPANDED_TERMS as f64 {
        return Err(AlgebraError::TooLarge {
            what: "multiplying out the difference of the sides".into(),
            size: format!("about {size:.1e}"),
            limit: EXPANDED_TERMS,
        });
    }
    numerator.expand()
}

/// Whether `difference` is zero: its numerator multiplied out (within [`EXPANDED_TERMS`]),
/// then with the trigonometric and radical identities ([`reduced_is_zero`]).
pub(in crate::check) fn is_zero(
    difference: &Expr,
    domains: &Domains,
) -> Result<bool, AlgebraError> {
    let numerator = expanded_numerator(difference)?;
    Ok(numerator.is_zero() || reduced_is_zero(&numerator, difference, domains)?)
}

/// Whether `difference` is zero once `sin² + cos² = 1`, the double angles, roots and
/// lowest terms are applied (the shortest form [`Expr::simplify`] reaches).
/// `expanded_numerator` is [`expanded_numerator`] of `difference`, already at hand.
fn reduced_is_zero(
    expanded_numerator: &Expr,
    difference: &Expr,
    domains: &Domains,
) -> Result<bool, AlgebraError> {
    if expanded_numerator.simplify_trig()?.is_zero() {
        return Ok(true);
    }
    Ok(difference.simplify(domains)?.is_zero())
}

/// A seed from the claim's text (FNV-1a), so that a check is the same on every run.
fn seed_of(text: &str) -> u64 {
    text.bytes().fold(0xcbf2_9ce4_8422_2325, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    })
}
