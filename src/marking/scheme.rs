//! A marking scheme (TOML): the questions of an assignment, each with where its answers are
//! checked, what an answer must give, its marks, the credit for a line that carries an
//! earlier slip, and the instructor's words for the slips they expect.
//!
//! ```toml
//! carried_forward = 0.5            # default for every question: half marks for a line
//!                                  # right from an earlier wrong one
//! [[question]]
//! id = "Q1"
//! scene = "../scenes/sp18_4_shaft_reactions.scene"   # relative to the scheme
//! gives = ["Hdot_z", "D_y"]        # each a step, the marks shared among them
//! may_use = ["I_xz", "I_xy", "alpha"]  # what a step may be left in besides the givens
//! marks = 4
//! [question.feedback]
//! scaled = "Take the moment of D about C as r × F, with r = L i."
//!
//! [[question]]
//! id = "Q2"
//! context = "principal"            # or general, fixed-point, "principal fixed-point", fixed-axis
//! gives = "SumM_x"
//! marks = 2
//! ```
//!
//! Every error stands at the place in the scheme that causes it.

use crate::check::context::Context;
use crate::parse::claim::Name;
use crate::parse::Diagnostic;
use std::collections::BTreeMap;
use std::ops::Range;
use toml::Spanned;

/// Where a question's answers are checked.
#[derive(Debug, Clone, PartialEq)]
pub enum Setting {
    /// A scene file, as the scheme writes its path (relative to the scheme).
    Scene(String),
    /// A general body in body-fixed axes (`check`'s default), with the principal-axes and
    /// fixed-point options.
    General { principal: bool, fixed_point: bool },
    /// Rotation about the fixed axis z.
    FixedAxis,
}

/// One question of a scheme.
#[derive(Debug, Clone)]
pub struct Question {
    /// Its column in the gradebook.
    pub id: String,
    pub setting: Setting,
    /// The quantities an answer must give (`D_y`), each a step: the answer's last line
    /// `D_y = …` is marked for it.
    pub gives: Vec<String>,
    pub marks: f64,
    /// Derived quantities a step's value may be left in (`alpha`, `I_xz`); otherwise it must
    /// be in the givens once the answer's own lines are put in.
    pub may_use: Vec<String>,
    /// Where `gives` stands in the scheme, for an error about a name of it.
    pub gives_span: Range<usize>,
    /// The fraction of a step's marks for a line that is wrong only because it carries an
    /// earlier slip (from 0 to 1).
    pub carried_forward: f64,
    /// The instructor's words beside kinetics' own, by the name of the slip.
    pub feedback: BTreeMap<String, String>,
}

/// A scheme: its questions, in the gradebook's order.
#[derive(Debug, Clone)]
pub struct Scheme {
    pub questions: Vec<Question>,
}

impl Scheme {
    /// The question with the id `id`.
    pub fn question(&self, id: &str) -> Option<usize> {
        self.questions.iter().position(|q| q.id == id)
    }
}

/// The credit for a carried line unless the scheme says otherwise: half its step's marks
/// (the slip costs marks once where it is made, and again, halved, in each step it carries
/// into: an answer of one step right only from a slip is not full marks).
pub const DEFAULT_CARRIED_FORWARD: f64 = 0.5;

#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct RawScheme {
    carried_forward: Option<Spanned<f64>>,
    question: Option<Vec<RawQuestion>>,
}

#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct RawQuestion {
    id: Spanned<String>,
    scene: Option<Spanned<String>>,
    context: Option<Spanned<String>>,
    gives: Spanned<Gives>,
    marks: Spanned<f64>,
    may_use: Option<Spanned<Vec<String>>>,
    carried_forward: Option<Spanned<f64>>,
    #[serde(default)]
    feedback: BTreeMap<Spanned<String>, String>,
}

/// `gives = "D_y"` or `gives = ["Hdot_z", "D_y"]`.
#[derive(serde::Deserialize)]
#[serde(untagged)]
enum Gives {
    One(String),
    Steps(Vec<String>),
}

/// Reads a scheme. `slip_names` are the names a feedback entry may be for (the checker's
/// readings).
pub fn parse_scheme(
    source_name: &str,
    source: &str,
    slip_names: &[&str],
) -> Result<Scheme, Box<Diagnostic>> {
    let error = |span: Range<usize>, message: String, help: &str| {
        Box::new(Diagnostic::at(source_name, source, span.start, span.end, message).with_help(help))
    };
    let raw: RawScheme = toml::from_str(source).map_err(|e| {
        let span = e.span().unwrap_or(0..0);
        error(
            span,
            format!("the scheme is not the TOML expected: {}", e.message()),
            "a scheme is [[question]] tables with id, scene or context, gives and marks",
        )
    })?;
    let fraction = |v: &Option<Spanned<f64>>, default: f64| match v {
        None => Ok(default),
        Some(f) if (0.0..=1.0).contains(f.get_ref()) => Ok(*f.get_ref()),
        Some(f) => Err(error(
            f.span(),
            format!(
                "carried_forward is {}: it is a fraction of the marks",
                f.get_ref()
            ),
            "give a number from 0 (no credit) to 1 (full credit)",
        )),
    };
    let default = fraction(&raw.carried_forward, DEFAULT_CARRIED_FORWARD)?;
    let raws = raw.question.unwrap_or_default();
    if raws.is_empty() {
        return Err(error(
            0..0,
            "the scheme has no question".into(),
            "add a [[question]] table with id, scene or context, gives and marks",
        ));
    }
    let mut questions: Vec<Question> = Vec::with_capacity(raws.len());
    for q in raws {
        let id = q.id.get_ref().trim().to_string();
        if id.is_empty() || id.contains([',', '"', '\n', '\r']) {
            return Err(error(
                q.id.span(),
                format!("the id {:?} cannot head a gradebook column", q.id.get_ref()),
                "give a short id without commas or quotes, like Q1",
            ));
        }
        if questions.iter().any(|p| p.id == id) {
            return Err(error(
                q.id.span(),
                format!("a second question {id}"),
                "every question has an id of its own",
            ));
        }
        let setting = match (&q.scene, &q.context) {
            (Some(scene), None) => Setting::Scene(scene.get_ref().clone()),
            (None, Some(context)) => setting(context.get_ref()).ok_or_else(|| {
                error(
                    context.span(),
                    format!("unknown context {:?}", context.get_ref()),
                    "a context is general, principal, fixed-point, \"principal fixed-point\" or fixed-axis",
                )
            })?,
            (Some(scene), Some(_)) => {
                return Err(error(
                    scene.span(),
                    format!("question {id} has both a scene and a context"),
                    "give one: the scene's file, or a context",
                ))
            }
            (None, None) => {
                return Err(error(
                    q.id.span(),
                    format!("question {id} has neither a scene nor a context"),
                    "give scene = \"FILE\" or context = \"general\"",
                ))
            }
        };
        let gives = match q.gives.get_ref() {
            Gives::One(name) => vec![name.trim().to_string()],
            Gives::Steps(names) => names.iter().map(|n| n.trim().to_string()).collect(),
        };
        let help = "name the quantities the answer gives, like gives = [\"Hdot_z\", \"D_y\"]";
        if gives.is_empty() {
            return Err(error(
                q.gives.span(),
                format!("question {id} gives nothing"),
                help,
            ));
        }
        if let Some(bad) = gives.iter().find(|g| !is_name(g)) {
            return Err(error(
                q.gives.span(),
                format!("question {id}: {bad:?} in gives is not a name"),
                help,
            ));
        }
        if let Some(twice) = gives
            .iter()
            .enumerate()
            .find(|(k, g)| gives[..*k].contains(g))
        {
            return Err(error(
                q.gives.span(),
                format!("question {id} gives {} twice", twice.1),
                "each step is a quantity of its own",
            ));
        }
        let may_use = match &q.may_use {
            None => Vec::new(),
            Some(names) => match names.get_ref().iter().find(|n| !is_name(n)) {
                Some(bad) => {
                    return Err(error(
                        names.span(),
                        format!("question {id}: {bad:?} in may_use is not a name"),
                        "name the quantities an answer may leave its value in, like may_use = [\"alpha\"]",
                    ))
                }
                None => names.get_ref().clone(),
            },
        };
        let marks = *q.marks.get_ref();
        if !(marks.is_finite() && marks > 0.0) {
            return Err(error(
                q.marks.span(),
                format!("question {id} has {marks} marks"),
                "give a positive number of marks",
            ));
        }
        let mut feedback = BTreeMap::new();
        for (slip, words) in q.feedback {
            if !slip_names.contains(&slip.get_ref().as_str()) {
                return Err(error(
                    slip.span(),
                    format!("no slip is named {:?}", slip.get_ref()),
                    &format!("the slips the checker names: {}", slip_names.join(", ")),
                ));
            }
            feedback.insert(slip.into_inner(), words);
        }
        questions.push(Question {
            id,
            setting,
            gives,
            marks,
            may_use,
            gives_span: q.gives.span(),
            carried_forward: fraction(&q.carried_forward, default)?,
            feedback,
        });
    }
    Ok(Scheme { questions })
}

/// The setting a `context` names: its words in any order.
fn setting(words: &str) -> Option<Setting> {
    let mut words: Vec<&str> = words.split_whitespace().collect();
    words.sort_unstable();
    Some(match words.as_slice() {
        ["general"] => Setting::General {
            principal: false,
            fixed_point: false,
        },
        ["principal"] => Setting::General {
            principal: true,
            fixed_point: false,
        },
        ["fixed-point"] => Setting::General {
            principal: false,
            fixed_point: true,
        },
        ["fixed-point", "principal"] => Setting::General {
            principal: true,
            fixed_point: true,
        },
        ["fixed-axis"] => Setting::FixedAxis,
        _ => return None,
    })
}

/// Whether `text` is a name as a claim writes one: a letter, then letters, digits, `_`, `'`.
fn is_name(text: &str) -> bool {
    let mut chars = text.chars();
    chars.next().is_some_and(|c| c.is_ascii_alphabetic())
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '\'')
}

/// Checks that every name a question gives or lets an answer use is a quantity its context
/// derives (`contexts[k]` for question k): a misspelt `T_CB` is an error at its `gives`,
/// with the context's suggestion, not a step no answer can state.
pub fn check_names(
    scheme: &Scheme,
    contexts: &[Context],
    source_name: &str,
    source: &str,
) -> Result<(), Box<Diagnostic>> {
    for (q, context) in scheme.questions.iter().zip(contexts) {
        for (key, names) in [("gives", &q.gives), ("may_use", &q.may_use)] {
            for name in names {
                let why = match context.name(name) {
                    Name::Derived(_) if context.is_alias(name) => {
                        format!("{name} is another spelling of givens, not a quantity to derive")
                    }
                    Name::Derived(_) if context.derived_scalar(name).is_none() => format!(
                        "{name} is a vector: give its components as steps, as check names them (H_x, H_y, H_z)"
                    ),
                    Name::Derived(_) => continue,
                    Name::Unknown(help) => help,
                    _ => format!(
                        "{name} is not among the quantities {} derives",
                        context.description
                    ),
                };
                return Err(Box::new(
                    Diagnostic::at(
                        source_name,
                        source,
                        q.gives_span.start,
                        q.gives_span.end,
                        format!(
                            "question {}: {key} cannot name {name} in {}",
                            q.id, context.description
                        ),
                    )
                    .with_help(why),
                ));
            }
        }
    }
    Ok(())
}
