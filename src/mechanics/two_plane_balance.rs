//! Two-plane balancing as a request (§18.8): two correction masses `m_1`, `m_2` at the radius
//! `r` in the planes `a = a_1`, `a = a_2` across the shaft axis `a` (z, or x, y), at the
//! angles `θ_1`, `θ_2` measured about the axis from the next axis `b` in cyclic order toward
//! `c` (about z: from x toward y; about x: from y toward z). With the linear unknowns
//! `P_k = m_k r cos θ_k`, `Q_k = m_k r sin θ_k`, static balance and `I_ab = I_ac = 0` after
//! correction are two linear systems (no nonlinear solver):
//!
//! ```text
//! P_1 + P_2 = -S_b          a_1 P_1 + a_2 P_2 = -I_ab
//! Q_1 + Q_2 = -S_c          a_1 Q_1 + a_2 Q_2 = -I_ac
//! ```
//!
//! (`S_b = m b̄`, `S_c = m c̄` and `I_ab`, `I_ac` about O, solved in
//! [`dynamic_balancing`]); then `m_k = √(P_k² + Q_k²)/r` and `θ_k = atan2(Q_k, P_k)`,
//! exact at the multiples of 15° (`Q_k cos θ = P_k sin θ` with `P_k cos θ + Q_k sin θ ≥ 0`),
//! undefined where `P_k = Q_k = 0` (no correction in that plane).
//!
//! The residual: the corrected body has `S'_b = S_b + P_1 + P_2`, `S'_c`, `I'_ab = I_ab +
//! a_1 P_1 + a_2 P_2` and `I'_ac`, all zero, and its dynamic bearing reactions are derived by
//! [`bearing_reactions`] (bearings A at `a = a_A`, B at `a = a_B`; products about A are
//! `I'_ab − a_A S'_b`), or, without bearings, the effective force `m' ā` and the moments
//! across the axis of [`fixed_axis_rotation`] are shown. The moments `I_b`, `I_c` and the
//! product `I_bc` enter neither; `I'_a = I_a + (m_1 + m_2) r²`.

use super::balancing::{dynamic_balancing, Unbalance};
use super::derivation::{Derivation, Relation, Step};
use super::fixed_axis::{bearing_reactions, fixed_axis_rotation};
use super::inertia::InertiaTensor;
use crate::algebra::{AlgebraError, Axis, Domains, Expr, Func, Symbol};
use std::f64::consts::PI;

const AXES: [Axis; 3] = [Axis::X, Axis::Y, Axis::Z];
const LETTERS: [&str; 3] = ["x", "y", "z"];

/// The body turning about the shaft axis, before correction: its mass, its first moments
/// across the axis `(S_b, S_c)` and its inertia about O.
pub struct Rotor<'a> {
    pub mass: &'a Expr,
    pub first_moment: (&'a Expr, &'a Expr),
    pub inertia: &'a InertiaTensor,
}

/// Where the correction masses go: the planes `a = a_1`, `a = a_2` across `axis`, at `radius`.
pub struct Planes<'a> {
    pub axis: Axis,
    pub positions: (&'a Expr, &'a Expr),
    pub radius: &'a Expr,
    /// The subscripts of the two corrections' names (`1`, `2`: `m_1`, `θ_1`, `P_1`, `Q_1`),
    /// chosen apart from the scene's own names.
    pub labels: [&'a str; 2],
}

/// The angle of a correction mass about the shaft axis.
#[derive(Debug, Clone, PartialEq)]
pub enum CorrectionAngle {
    /// An exact multiple of π/12, in radians, in (−π, π].
    Exact(Expr),
    /// `atan2(Q, P)`: a number once `P` and `Q` have values.
    Atan2 { q: Expr, p: Expr },
    /// No correction in the plane (`P = Q = 0`): no angle.
    Undefined,
}

/// One correction mass: its plane, `P = m r cos θ`, `Q = m r sin θ`, its mass and angle.
#[derive(Debug, Clone, PartialEq)]
pub struct Correction {
    /// The subscript of its names (`1` in `m_1`).
    pub label: String,
    pub plane: Expr,
    pub p: Expr,
    pub q: Expr,
    pub mass: Expr,
    pub angle: CorrectionAngle,
}

/// The index in [`InertiaTensor::products`] (`[I_xy, I_yz, I_xz]`) of the product of axes `i`, `j`.
fn product_index(i: usize, j: usize) -> usize {
    match (i.min(j), i.max(j)) {
        (0, 1) => 0,
        (1, 2) => 1,
        _ => 2,
    }
}

/// The symbol `I_ij`, its subscripts in alphabetical order.
fn product_name(i: usize, j: usize) -> String {
    format!("I_{}{}", LETTERS[i.min(j)], LETTERS[i.max(j)])
}

/// `I_{ij}` in a step title's markup.
fn product_markup(i: usize, j: usize) -> String {
    format!("I_{{{}{}}}", LETTERS[i.min(j)], LETTERS[i.max(j)])
}

/// `m = √(P² + Q²)/r`; over a common denominator `D`, `√(p² + q²)/(|D| r)`.
fn correction_mass(p: &Expr, q: &Expr, radius: &Expr) -> Result<Expr, AlgebraError> {
    let half = Expr::rational(1, 2);
    let ((p_top, p_below), (q_top, q_below)) = (p.cancelled_parts()?, q.cancelled_parts()?);
    let (top, below) = if p_below == q_below || q.is_zero() {
        (p_top.powi(2) + q_top.powi(2), p_below)
    } else if p.is_zero() {
        (q_top.powi(2), q_below)
    } else {
        (p.powi(2) + q.powi(2), Expr::one())
    };
    top.checked_pow(&half)?
        .checked_div(&(Func::Abs.apply(below) * radius))
}

/// `atan2(q, p)` exactly at the multiples of 15°, where the signs of the domains decide it.
/// Only the multiple nearest the angle at a probe point (each symbol a number in [1, 2) from
/// its name) is tried exactly, unless the probe has no angle; a test too large to expand
/// leaves the angle to `atan2` of the values.
fn angle(p: &Expr, q: &Expr, domains: &Domains) -> CorrectionAngle {
    if p.is_zero() && q.is_zero() {
        return CorrectionAngle::Undefined;
    }
    let probe = |s: Symbol| {
        let spread = s
            .name()
            .bytes()
            .fold(7u32, |h, b| h.wrapping_mul(31) ^ u32::from(b));
        Some(1.0 + f64::from(spread % 1000) / 1000.0)
    };
    let near = match (p.eval::<f64>(&probe), q.eval::<f64>(&probe)) {
        (Ok(x), Ok(y)) if x != 0.0 || y != 0.0 => Some((y.atan2(x) * 12.0 / PI).round() as i64),
        _ => None,
    };
    for k in -11..=12 {
        // -π and π are one direction.
        if near.is_some_and(|n| n != k && !(n == -12 && k == 12)) {
            continue;
        }
        let theta = Expr::pi() * Expr::rational(k, 12);
        let (c, s) = (
            Func::Cos.apply(theta.clone()),
            Func::Sin.apply(theta.clone()),
        );
        let across = (q * &c - p * &s).expand();
        let along = (p * &c + q * &s).expand();
        if let (Ok(across), Ok(rho)) = (across, along) {
            if across.is_zero() && !rho.is_zero() && domains.sign(&rho).is_nonnegative() {
                return CorrectionAngle::Exact(theta);
            }
        }
    }
    CorrectionAngle::Atan2 {
        q: q.clone(),
        p: p.clone(),
    }
}

/// The two correction masses and their angles, with the steps: the unbalance, the two
/// linear systems and their solutions, the masses and angles, the corrected body and its
/// residual bearing reactions (zero). `bearings`: the axial positions of bearings A and B.
pub fn two_plane_balance(
    rotor: &Rotor,
    planes: &Planes,
    bearings: Option<(&Expr, &Expr)>,
    domains: &Domains,
) -> Result<([Correction; 2], Derivation), AlgebraError> {
    let a = planes.axis.index();
    let (b, c) = ((a + 1) % 3, (a + 2) % 3);
    let (la, lb, lc) = (LETTERS[a], LETTERS[b], LETTERS[c]);
    let products = &rotor.inertia.products;
    let (i_ab, i_ac) = (
        &products[product_index(a, b)],
        &products[product_index(a, c)],
    );
    let (s_b, s_c) = rotor.first_moment;
    let (a_1, a_2) = planes.positions;
    let solved = dynamic_balancing(
        &Unbalance {
            first_moment: (s_b, s_c),
            products: (i_ab, i_ac),
        },
        a_1,
        a_2,
        planes.axis,
    )?;
    let r: Vec<Expr> = solved
        .result()
        .iter()
        .map(|r| r.rhs.cancel())
        .collect::<Result<_, _>>()?;
    let (p, q) = ([r[0].clone(), r[1].clone()], [r[2].clone(), r[3].clone()]);
    let sym = |name: &str| Expr::symbol(name);
    // k = 1, 2: the plane's label.
    let named = |letter: &str, k: usize| sym(&format!("{letter}_{}", planes.labels[k - 1]));
    let (name_s_b, name_s_c) = (sym(&format!("S_{lb}")), sym(&format!("S_{lc}")));
    let (name_i_ab, name_i_ac) = (sym(&product_name(a, b)), sym(&product_name(a, c)));
    let mut steps = vec![Step::new(
        format!(
            r"the unbalance about $O$: first moments $S_{lb} = m\bar{{{lb}}}$, $S_{lc} = m\bar{{{lc}}}$ across the axis ${la}$ and the products ${}$, ${}$",
            product_markup(a, b),
            product_markup(a, c)
        ),
        vec![
            Relation::new(name_s_b.clone(), s_b.clone(), AXES[b]),
            Relation::new(name_s_c.clone(), s_c.clone(), AXES[c]),
            Relation::new(name_i_ab.clone(), i_ab.clone(), AXES[b]),
            Relation::new(name_i_ac.clone(), i_ac.clone(), AXES[c]),
        ],
    )];
    let sum = |letter: &str| named(letter, 1) + named(letter, 2);
    let moment = |letter: &str| a_1 * named(letter, 1) + a_2 * named(letter, 2);
    steps.push(Step::new(
        format!(
            r"correction masses $m_k$ at radius $r$ in the planes ${la} = {la}_k$, at $\theta_k$ about ${la}$ from ${lb}$ toward ${lc}$: with $P_k = m_k r\,\mathrm{{cos}}\,\theta_k$, $Q_k = m_k r\,\mathrm{{sin}}\,\theta_k$ the corrected body has $\bar{{{lb}}} = \bar{{{lc}}} = 0$ and ${} = {} = 0$",
            product_markup(a, b),
            product_markup(a, c)
        ),
        vec![
            Relation::new(sum("P"), -s_b, AXES[b]),
            Relation::new(moment("P"), -i_ab, AXES[b]),
            Relation::new(sum("Q"), -s_c, AXES[c]),
            Relation::new(moment("Q"), -i_ac, AXES[c]),
        ],
    ));
    steps.push(Step::new(
        "the two linear systems solved",
        vec![
            Relation::new(named("P", 1), p[0].clone(), AXES[b]),
            Relation::new(named("P", 2), p[1].clone(), AXES[b]),
            Relation::new(named("Q", 1), q[0].clone(), AXES[c]),
            Relation::new(named("Q", 2), q[1].clone(), AXES[c]),
        ],
    ));
    let mut corrections = Vec::with_capacity(2);
    let mut relations = Vec::with_capacity(4);
    let mut undefined = Vec::new();
    for k in 0..2 {
        let mass = correction_mass(&p[k], &q[k], planes.radius)?;
        let angle = angle(&p[k], &q[k], domains);
        let theta = named(r"theta", k + 1);
        relations.push(Relation::new(named("m", k + 1), mass.clone(), AXES[a]));
        match &angle {
            CorrectionAngle::Exact(t) => relations.push(Relation::new(theta, t.clone(), AXES[a])),
            CorrectionAngle::Atan2 { q, p } if !p.is_zero() => relations.push(Relation::new(
                Func::Tan.apply(theta),
                q.checked_div(p)?,
                AXES[a],
            )),
            CorrectionAngle::Atan2 { .. } => {
                relations.push(Relation::new(Func::Cos.apply(theta), Expr::zero(), AXES[a]))
            }
            CorrectionAngle::Undefined => {
                undefined.push(format!(r"$\theta_{{{}}}$", planes.labels[k]))
            }
        }
        corrections.push(Correction {
            label: planes.labels[k].to_string(),
            plane: [a_1, a_2][k].clone(),
            p: p[k].clone(),
            q: q[k].clone(),
            mass,
            angle,
        });
    }
    let undefined = match undefined.as_slice() {
        [] => String::new(),
        names => format!(
            "; no correction is needed where $m_k = 0$, and {} is undefined",
            names.join(" and ")
        ),
    };
    steps.push(Step::new(
        format!(
            r"the masses $m_k = (P_k^2 + Q_k^2)^{{1/2}}/r$ and angles $\theta_k = \mathrm{{atan2}}(Q_k, P_k)$, in the quadrant of $(P_k, Q_k)${undefined}"
        ),
        relations,
    ));
    steps.extend(residual(rotor, planes, &p, &q, &corrections, bearings)?.steps);
    let [first, second]: [Correction; 2] = corrections
        .try_into()
        .unwrap_or_else(|_| unreachable!("two planes"));
    Ok((
        [first, second],
        Derivation {
            name: "two_plane_balance".into(),
            title: "two-plane balancing with correction masses".into(),
            steps,
        },
    ))
}

/// The corrected body's first moments and products across the axis (each zero, brought to
/// lowest terms) and its dynamic bearing reactions, or its effective force and moments.
fn residual(
    rotor: &Rotor,
    planes: &Planes,
    p: &[Expr; 2],
    q: &[Expr; 2],
    corrections: &[Correction],
    bearings: Option<(&Expr, &Expr)>,
) -> Result<Derivation, AlgebraError> {
    let a = planes.axis.index();
    let (b, c) = ((a + 1) % 3, (a + 2) % 3);
    let (a_1, a_2) = planes.positions;
    let (s_b, s_c) = rotor.first_moment;
    let products = &rotor.inertia.products;
    let (i_ab, i_ac) = (
        &products[product_index(a, b)],
        &products[product_index(a, c)],
    );
    let corrected_s_b = (s_b + &p[0] + &p[1]).cancel()?;
    let corrected_s_c = (s_c + &q[0] + &q[1]).cancel()?;
    let corrected_i_ab = (i_ab + a_1 * &p[0] + a_2 * &p[1]).cancel()?;
    let corrected_i_ac = (i_ac + a_1 * &q[0] + a_2 * &q[1]).cancel()?;
    let sym = |name: &str| Expr::symbol(name);
    // k = 1, 2: the plane's label.
    let named = |letter: &str, k: usize| sym(&format!("{letter}_{}", planes.labels[k - 1]));
    let (s_b_name, s_c_name) = (
        sym(&format!("S_{}", LETTERS[b])),
        sym(&format!("S_{}", LETTERS[c])),
    );
    let (i_ab_name, i_ac_name) = (sym(&product_name(a, b)), sym(&product_name(a, c)));
    let moment = |letter: &str| a_1 * named(letter, 1) + a_2 * named(letter, 2);
    let mut steps = vec![Step::new(
        format!(
            r"the corrected body: $S_{lb}' = S_{lb} + P_{{{k1}}} + P_{{{k2}}}$, $S_{lc}'$, ${ab}' = {ab} + {la}_{{{k1}}} P_{{{k1}}} + {la}_{{{k2}}} P_{{{k2}}}$, ${ac}'$",
            k1 = planes.labels[0],
            k2 = planes.labels[1],
            lb = LETTERS[b],
            lc = LETTERS[c],
            la = LETTERS[a],
            ab = product_markup(a, b),
            ac = product_markup(a, c),
        ),
        vec![
            Relation::new(
                &s_b_name + named("P", 1) + named("P", 2),
                corrected_s_b.clone(),
                AXES[b],
            ),
            Relation::new(
                &s_c_name + named("Q", 1) + named("Q", 2),
                corrected_s_c.clone(),
                AXES[c],
            ),
            Relation::new(i_ab_name + moment("P"), corrected_i_ab.clone(), AXES[b]),
            Relation::new(i_ac_name + moment("Q"), corrected_i_ac.clone(), AXES[c]),
        ],
    )];
    let added = corrections
        .iter()
        .map(|k| &k.mass)
        .fold(Expr::zero(), |s, m| s + m);
    let mass = rotor.mass + &added;
    let mut moments = rotor.inertia.moments.clone();
    moments[a] = &moments[a] + &added * planes.radius.powi(2);
    let mut corrected = rotor.inertia.products.clone();
    corrected[product_index(a, b)] = corrected_i_ab.clone();
    corrected[product_index(a, c)] = corrected_i_ac.clone();
    let centroid = (
        corrected_s_b.checked_div(&mass)?,
        corrected_s_c.checked_div(&mass)?,
    );
    let reactions = match bearings {
        Some((a_a, a_b)) => {
            // Products about A, at a = a_A on the axis: ∫(a − a_A) b dm = I_ab − a_A S_b.
            corrected[product_index(a, b)] = (&corrected_i_ab - a_a * &corrected_s_b).cancel()?;
            corrected[product_index(a, c)] = (&corrected_i_ac - a_a * &corrected_s_c).cancel()?;
            let inertia = InertiaTensor {
                moments,
                products: corrected,
            };
            let mut d = bearing_reactions(
                &inertia,
                &mass,
                (&centroid.0, &centroid.1),
                &(a_b - a_a),
                planes.axis,
            )?;
            if let Some(first) = d.steps.first_mut() {
                first.title = format!(
                    r"residual dynamic reactions after correction, the scene's bearings $A$ and $B$ on the axis ${la}$, $l$ apart; {}",
                    first.title,
                    la = LETTERS[a]
                );
                first
                    .relations
                    .insert(0, Relation::new(sym("l"), a_b - a_a, AXES[a]));
            }
            d
        }
        None => {
            let inertia = InertiaTensor {
                moments,
                products: corrected,
            };
            let fixed = fixed_axis_rotation(&inertia, planes.axis)?;
            let sum_m: Vec<Expr> = fixed.result().iter().map(|r| r.rhs.clone()).collect();
            let (w, alpha) = (sym("w"), sym("alpha"));
            let effective_b = -(&alpha * &corrected_s_c) - w.powi(2) * &corrected_s_b;
            let effective_c = &alpha * &corrected_s_b - w.powi(2) * &corrected_s_c;
            let sum = |letter: &str, k: usize| sym(&format!("Sum{letter}_{}", LETTERS[k]));
            Derivation {
                name: "residual".into(),
                title: "residual effective forces".into(),
                steps: vec![Step::new(
                    format!(
                        r"residual after correction (no bearings on the axis in the scene): the effective force $m'\bar{{\mathbf{{a}}}}$ and the moments across the axis, $\Sigma M_{} = \Sigma M_{} = 0$",
                        LETTERS[b], LETTERS[c]
                    ),
                    vec![
                        Relation::new(sum("F", b), effective_b.expand()?, AXES[b]),
                        Relation::new(sum("F", c), effective_c.expand()?, AXES[c]),
                        Relation::new(sum("M", b), sum_m[b].expand()?, AXES[b]),
                        Relation::new(sum("M", c), sum_m[c].expand()?, AXES[c]),
                    ],
                )],
            }
        }
    };
    steps.extend(reactions.steps);
    Ok(Derivation {
        name: "residual".into(),
        title: "residual reactions after correction".into(),
        steps,
    })
}
