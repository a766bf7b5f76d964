//! A check's report as a person reads it: text, LaTeX, or JSON.
//!
//! Each differing component shows the correct form beside the claimed one, both in the
//! textbook's form ([`Forms`]), the residual `claimed − correct`, the wrong, missing
//! and extra terms, and the reading of the slip when one fits.
//!
//! A report stays short and quick however large the claim: a large form is shown in
//! canonical order ([`Forms`]), and a list of wrong, missing or extra terms shows its first
//! [`LISTED_TERMS`] and counts the rest (`(a+b+c+d)^21 = 1/T` has thousands, each over T's denominator).

use super::diagnosis::Diagnosis;
use super::dimension::OddTerm;
use super::forms::Forms;
use super::verdict::{Component, Numbers, Piece, Report, Verdict};
use crate::algebra::significant_figures;
use crate::algebra::{Axis, Expr};
use crate::parse::parse_expression;
use crate::print::{self, markup, Notation};
use serde_json::{json, Value as Json};

impl Verdict {
    /// The verdict as a word: `holds`, `differs`, `undecided`.
    pub fn word(self) -> &'static str {
        match self {
            Verdict::Holds => "holds",
            Verdict::Differs => "differs",
            Verdict::Undecided => "undecided",
        }
    }
}

fn axis_name(axis: Option<Axis>) -> &'static str {
    match axis {
        None => "",
        Some(Axis::X) => "i",
        Some(Axis::Y) => "j",
        Some(Axis::Z) => "k",
    }
}

/// The most terms a list of wrong, missing or extra terms shows.
const LISTED_TERMS: usize = 12;

fn shown(e: &Expr, axis: Option<Axis>, notation: Notation, forms: &Forms) -> String {
    print::render(&forms.readable(e), notation, axis.unwrap_or(Axis::Z))
}

/// The terms a list shows, and how many more it has.
fn listed<T>(terms: &[T]) -> (&[T], usize) {
    let shown = terms.len().min(LISTED_TERMS);
    (&terms[..shown], terms.len() - shown)
}

/// The components a report shows: those that do not hold.
fn not_holding(report: &Report) -> impl Iterator<Item = &Component> {
    report
        .components
        .iter()
        .filter(|c| c.verdict != Verdict::Holds)
}

/// A component's term-by-term diagnosis, shown where no slip of the mechanics explains the
/// claim (the slip's line says what differs, once).
fn term_by_term<'r>(report: &Report, c: &'r Component) -> Option<&'r Diagnosis> {
    c.diagnosis.as_ref().filter(|_| report.slip.is_none())
}

/// `in solution 2 of the 2 the scene's equations have`.
fn solution_sentence(report: &Report) -> String {
    format!(
        "in solution {} of the {} the scene's equations have",
        report.solution + 1,
        report.solutions
    )
}

/// The significant figures a report shows a claimed number in: as many as the tolerance
/// asks for (four at the default 0.5 %, one more a tenfold tighter).
fn figures(n: &Numbers) -> usize {
    (1.0 - n.tolerance.log10()).ceil().clamp(4.0, 16.0) as usize
}

/// A number with the unit of its component (in the scene's unit system).
fn number(x: f64, digits: usize, n: &Numbers) -> String {
    let unit = n.unit.as_ref().map(|u| format!(" {u}")).unwrap_or_default();
    format!("{}{unit}", significant_figures(x, digits))
}

/// The quantity a component of the correct side is: `D_z`, `H_O, j component`.
fn component_label(report: &Report, axis: Option<Axis>) -> String {
    match axis {
        None => report.correct_side.clone(),
        Some(_) => format!("{}, {} component", report.correct_side, axis_name(axis)),
    }
}

/// What the slip changes in a component, in the givens' names and, for a claim in
/// numbers, in value: `correct − claimed = -1/8*m*c*w^2 (-59.25 N)`.
fn piece_text(piece: &Piece, c: Option<&Component>, notation: Notation, forms: &Forms) -> String {
    let form = shown(&piece.in_symbols, piece.axis, notation, forms);
    let value = piece
        .value
        .zip(c.and_then(|c| c.numbers.as_ref()))
        .map(|(v, n)| format!(" ({})", number(v, figures(n), n)))
        .unwrap_or_default();
    match notation {
        Notation::Latex => format!(r"$\text{{correct}} - \text{{claimed}} = {form}${value}"),
        _ => format!("correct - claimed = {form}{value}"),
    }
}

/// `1900 N is 2.3 % from the exact 1857 N; the tolerance is 0.5 %`.
pub fn numbers_sentence(n: &Numbers) -> String {
    // Two figures, or as many as tell a distance from the tolerance (0.502 %, never a
    // 0.50 % that fails beside a tolerance of 0.5 %).
    let percent = |r: f64| {
        let shown = |k: usize| significant_figures(100.0 * r, k);
        (2..=6)
            .map(shown)
            .find(|p| r == n.tolerance || p.parse::<f64>() != Ok(100.0 * n.tolerance))
            .unwrap_or_else(|| shown(6))
    };
    let digits = figures(n);
    let claimed = number(n.claimed, digits, n);
    // The exact value in the claim's figures where it differs (the answer to write), in one
    // more where it holds (to show how near it came).
    let correct = number(n.correct, digits + usize::from(n.holds()), n);
    let tolerance = percent(n.tolerance);
    let wrong_sign = n.claimed * n.correct < 0.0;
    match (n.relative, n.holds()) {
        (0.0, _) => format!("{claimed} is the exact value"),
        (_, false) if wrong_sign => {
            format!("{claimed} has the wrong sign: the exact value is {correct}")
        }
        (r, true) => format!(
            "{claimed} is {} % from the exact {correct}, within the tolerance of {tolerance} %",
            percent(r)
        ),
        (r, false) if r.is_finite() => format!(
            "{claimed} is {} % from the exact {correct}; the tolerance is {tolerance} %",
            percent(r)
        ),
        _ => format!("{claimed} where the exact value is {correct}"),
    }
}

/// The claim's report in text: the verdict, where the claim was written and the claim, then
/// for each component that does not hold the claimed and the correct forms, the residual and
/// the diagnosis.
pub fn text(report: &Report, label: &str, forms: &Forms) -> String {
    let mut out = format!("{} ({label}): {}\n", report.verdict.word(), report.claim);
    if let Some(odd) = &report.odd_term {
        out.push_str(&format!("  inhomogeneous: {}\n", odd_term_sentence(odd)));
        return out;
    }
    if report.solutions > 1 {
        out.push_str(&format!("  {}\n", solution_sentence(report)));
    }
    let of = |c: &Component| component_label(report, c.axis);
    for c in &report.components {
        if let Some(n) = &c.numbers {
            // A claim that differs, decided in numbers: the correct value in the givens'
            // names first, where it has any (what the student derives), then the numbers.
            if !n.holds() && !c.correct_in_symbols.symbols().is_empty() {
                let form = shown(&c.correct_in_symbols, c.axis, Notation::Text, forms);
                out.push_str(&format!("  {}, correct: {form}\n", of(c)));
            }
            out.push_str(&format!("  {}: {}\n", of(c), numbers_sentence(n)));
            if let Some(d) = term_by_term(report, c) {
                out.push_str(&diagnosis_text(d, c, forms));
            }
        }
    }
    if let Some(slip) = &report.slip {
        let concept = markup::text(slip.slip.concept());
        out.push_str(&format!("  {}: {concept}\n", slip.slip.name()));
        for piece in &slip.pieces {
            let c = report.components.iter().find(|c| c.axis == piece.axis);
            out.push_str(&format!(
                "    {}: {}\n",
                component_label(report, piece.axis),
                piece_text(piece, c, Notation::Text, forms)
            ));
        }
    }
    for c in not_holding(report).filter(|c| c.numbers.is_none()) {
        let of = of(c);
        let form = |e: &Expr| shown(e, c.axis, Notation::Text, forms);
        out.push_str(&format!("  {of}, as claimed: {}\n", form(&c.claimed)));
        out.push_str(&format!("  {of}, correct:    {}\n", form(&c.correct)));
        if let Some(why) = &c.undecided_because {
            out.push_str(&format!("  undecided: {why}\n"));
        }
        if let Some(d) = term_by_term(report, c) {
            out.push_str(&diagnosis_text(d, c, forms));
        }
    }
    out
}

/// What each component that does not hold should read: `D_y, correct: -3*M/(16*c) - …`
/// (in the givens' names, and in numbers for a claim written in them). In LaTeX
/// (`notation`), the label in words and the form as `$…$`.
pub fn correct_forms(report: &Report, notation: Notation, forms: &Forms) -> Vec<String> {
    not_holding(report)
        .map(|c| {
            let form = shown(&c.correct_in_symbols, c.axis, notation, forms);
            let value = c
                .numbers
                .as_ref()
                .filter(|_| !c.correct_in_symbols.symbols().is_empty())
                .map(|n| format!(" = {}", number(n.correct, figures(n), n)))
                .unwrap_or_default();
            let label = component_label(report, c.axis);
            match notation {
                Notation::Latex => format!(
                    "{}, correct: ${form}${}",
                    markup::latex_words(&label),
                    markup::latex_words(&value).replacen(" = -", " = $-$", 1)
                ),
                _ => format!("{label}, correct: {form}{value}"),
            }
        })
        .collect()
}

/// `the term X is in kg·m/s where ...`, or `the term X: the argument of sin must ...`.
fn odd_term_sentence(odd: &OddTerm) -> String {
    if odd.reason.starts_with("is ") {
        format!("the term {} {}", odd.text, odd.reason)
    } else {
        format!("the term {}: {}", odd.text, odd.reason)
    }
}

fn terms_text(terms: &[Expr], c: &Component, forms: &Forms) -> String {
    let (terms, more) = listed(terms);
    let mut out = terms
        .iter()
        .map(|t| shown(t, c.axis, Notation::Text, forms))
        .collect::<Vec<_>>()
        .join(", ");
    if more > 0 {
        out.push_str(&format!(", and {more} more"));
    }
    out
}

fn diagnosis_text(d: &Diagnosis, c: &Component, forms: &Forms) -> String {
    let mut out = String::new();
    // In the givens' names: a claim decided in numbers is diagnosed in them.
    let residual = &c.claimed_in_symbols - &c.correct_in_symbols;
    out.push_str(&format!(
        "  residual (claimed - correct): {}\n",
        shown(&residual, c.axis, Notation::Text, forms)
    ));
    if let Some(r) = &d.reading {
        out.push_str(&format!(
            "  {}: {}\n",
            r.name,
            in_component(&r.explanation, c)
        ));
    }
    let (wrong, more) = listed(&d.wrong);
    for w in wrong {
        out.push_str(&format!(
            "  wrong term: {} (correct: {})\n",
            shown(&w.claimed, c.axis, Notation::Text, forms),
            shown(&w.correct, c.axis, Notation::Text, forms)
        ));
    }
    if more > 0 {
        out.push_str(&format!("  and {more} more wrong terms\n"));
    }
    if !d.missing.is_empty() {
        out.push_str(&format!(
            "  missing: {}\n",
            terms_text(&d.missing, c, forms)
        ));
    }
    if !d.extra.is_empty() {
        out.push_str(&format!("  extra: {}\n", terms_text(&d.extra, c, forms)));
    }
    out
}

/// The side taken as correct in LaTeX: a derived quantity's side read back from its text
/// (`2 T`, `\Sigma M_x`); the side of a claim of pure algebra as written, in typewriter type
/// (read back, its cross products would be worked out).
fn side_latex(report: &Report) -> String {
    let written = || {
        format!(
            r"\text{{\texttt{{{}}}}}",
            markup::latex_words(&report.correct_side)
        )
    };
    if !report.correct_is_derived {
        return written();
    }
    parse_expression("side", &report.correct_side).map_or_else(|_| written(), |e| print::latex(&e))
}

/// The claim's report in LaTeX: a paragraph with the verdict, and for each component that
/// does not hold an `align*` of the claimed and the correct forms.
pub fn latex(report: &Report, label: &str, forms: &Forms) -> String {
    let reading = report
        .reading()
        .map(|r| format!(" ({})", r.replace('-', " ")))
        .unwrap_or_default();
    let mut out = format!(
        "\\paragraph{{{} {}{reading}.}} \\texttt{{{}}}\n",
        markup::latex_words(label),
        report.verdict.word(),
        markup::latex_words(&report.claim)
    );
    if let Some(odd) = &report.odd_term {
        out.push_str(&format!(
            "{}.\n",
            markup::latex_words(&odd_term_sentence(odd))
        ));
        return out;
    }
    if report.solutions > 1 {
        out.push_str(&format!(
            "{}.\n",
            markup::latex_words(&solution_sentence(report))
        ));
    }
    let name = side_latex(report);
    for n in report.components.iter().filter_map(|c| c.numbers.as_ref()) {
        out.push_str(&format!("{}.\n", markup::latex_words(&numbers_sentence(n))));
    }
    if let Some(slip) = &report.slip {
        out.push_str(&format!("{}.\n", markup::latex(slip.slip.concept())));
        for piece in &slip.pieces {
            let c = report.components.iter().find(|c| c.axis == piece.axis);
            out.push_str(&format!(
                "{}: {}.\n",
                markup::latex_words(&component_label(report, piece.axis)),
                piece_text(piece, c, Notation::Latex, forms)
            ));
        }
    }
    for c in not_holding(report).filter(|c| c.numbers.is_none()) {
        let of = match c.axis {
            None => name.clone(),
            Some(_) => format!(
                r"({name})_{}",
                print::latex(&Expr::symbol(axis_name(c.axis)))
            ),
        };
        let form = |e: &Expr| shown(e, c.axis, Notation::Latex, forms);
        out.push_str("\\begin{align*}\n");
        out.push_str(&format!(
            "  {of} &= {} && \\text{{as claimed}} \\\\\n",
            form(&c.claimed)
        ));
        out.push_str(&format!(
            "  {of} &= {} && \\text{{correct}}",
            form(&c.correct)
        ));
        if c.diagnosis.is_some() {
            out.push_str(&format!(
                " \\\\\n  \\text{{claimed}} - \\text{{correct}} &= {} && \\text{{residual}}",
                form(&(&c.claimed - &c.correct))
            ));
        }
        out.push_str("\n\\end{align*}\n");
        if let Some(why) = &c.undecided_because {
            out.push_str(&format!("Undecided: {}.\n", markup::latex_words(why)));
        }
        if let Some(d) = term_by_term(report, c) {
            out.push_str(&diagnosis_latex(d, c, forms));
        }
    }
    out
}

/// An explanation said of a vector's component: "the whole side" is "the whole j
/// component" there.
fn in_component(explanation: &str, c: &Component) -> String {
    match c.axis {
        None => explanation.to_string(),
        Some(_) => explanation.replace(
            "the whole side",
            &format!("the whole {} component", axis_name(c.axis)),
        ),
    }
}

/// The reading's explanation, then the wrong, missing and extra terms, typeset.
fn diagnosis_latex(d: &Diagnosis, c: &Component, forms: &Forms) -> String {
    let math = |e: &Expr| format!("${}$", shown(e, c.axis, Notation::Latex, forms));
    let list = |terms: &[Expr]| terms.iter().map(math).collect::<Vec<_>>().join(", ");
    let mut parts = Vec::new();
    if let Some(r) = &d.reading {
        parts.push(explanation_latex(&in_component(&r.explanation, c)));
    }
    for w in &d.wrong {
        parts.push(format!(
            "wrong term {} (correct: {})",
            math(&w.claimed),
            math(&w.correct)
        ));
    }
    if !d.missing.is_empty() {
        parts.push(format!("missing {}", list(&d.missing)));
    }
    if !d.extra.is_empty() {
        parts.push(format!("extra {}", list(&d.extra)));
    }
    format!("{}.\n", parts.join("; "))
}

/// An explanation in LaTeX: its words as text, each expression it marks with backticks
/// typeset as mathematics (as written, where one does not read back).
fn explanation_latex(explanation: &str) -> String {
    explanation
        .split('`')
        .enumerate()
        .map(
            |(k, piece)| match (k % 2, parse_expression("explanation", piece)) {
                (1, Ok(e)) => format!("${}$", print::latex(&e)),
                (1, Err(_)) => format!(r"\texttt{{{}}}", markup::latex_words(piece)),
                _ => markup::latex_words(piece),
            },
        )
        .collect()
}

/// The form in text and in LaTeX, simplified once for both.
fn both(e: &Expr, axis: Option<Axis>, forms: &Forms) -> Json {
    let (form, axis) = (forms.readable(e), axis.unwrap_or(Axis::Z));
    json!({
        "text": print::render(&form, Notation::Text, axis),
        "latex": print::render(&form, Notation::Latex, axis),
    })
}

fn diagnosis_json(d: &Diagnosis, axis: Option<Axis>, forms: &Forms) -> Json {
    let list = |terms: &[Expr]| -> Vec<Json> {
        listed(terms)
            .0
            .iter()
            .map(|t| both(t, axis, forms))
            .collect()
    };
    json!({
        "reading": d.reading.as_ref().map(|r| r.name),
        "explanation": d.reading.as_ref().map(|r| r.explanation.clone()),
        "wrong": listed(&d.wrong).0.iter().map(|w| json!({
            "claimed": both(&w.claimed, axis, forms),
            "correct": both(&w.correct, axis, forms),
        })).collect::<Vec<_>>(),
        "missing": list(&d.missing),
        "extra": list(&d.extra),
        // The terms beyond those listed, counted.
        "wrong_more": listed(&d.wrong).1,
        "missing_more": listed(&d.missing).1,
        "extra_more": listed(&d.extra).1,
    })
}

fn odd_term_json(odd: &OddTerm) -> Json {
    json!({
        "text": odd.text,
        "span": [odd.span.0, odd.span.1],
        "dimension": odd.dimension.map(|d| d.si_unit()),
        "expected": odd.expected.si_unit(),
        "reason": odd.reason,
    })
}

/// The claim's report as a JSON object (its `line` and `error` added by the caller).
pub fn json(report: &Report, forms: &Forms) -> Json {
    json!({
        "claim": report.claim,
        "verdict": report.verdict.word(),
        "reading": report.reading(),
        "error": Json::Null,
        "correct_side": report.correct_side,
        "claimed_side": report.claimed_side,
        "odd_term": report.odd_term.as_ref().map(odd_term_json),
        "solution": (report.solutions > 1).then(|| json!({
            "number": report.solution + 1,
            "of": report.solutions,
        })),
        "slip": report.slip.as_ref().map(|slip| json!({
            "name": slip.slip.name(),
            "explanation": markup::text(slip.slip.concept()),
            "explanation_latex": markup::latex(slip.slip.concept()),
            "pieces": slip.pieces.iter().map(|piece| json!({
                "axis": piece.axis.map(|a| ["x", "y", "z"][a as usize]),
                "form": both(&piece.in_symbols, piece.axis, forms),
                "value": piece.value,
            })).collect::<Vec<_>>(),
        })),
        "components": report.components.iter().map(|c| json!({
            "axis": c.axis.map(|a| ["x", "y", "z"][a as usize]),
            "verdict": c.verdict.word(),
            "claimed": both(&c.claimed, c.axis, forms),
            "correct": both(&c.correct, c.axis, forms),
            "residual": both(&(&c.claimed - &c.correct), c.axis, forms),
            "undecided_because": c.undecided_because,
            "numbers": c.numbers.as_ref().map(|n| json!({
                "correct": n.correct,
                "claimed": n.claimed,
                "relative": n.relative.is_finite().then_some(n.relative),
                "tolerance": n.tolerance,
                "unit": n.unit.as_ref().map(ToString::to_string),
                "sentence": numbers_sentence(n),
            })),
            "diagnosis": c.diagnosis.as_ref().map(|d| diagnosis_json(d, c.axis, forms)),
        })).collect::<Vec<_>>(),
    })
}
