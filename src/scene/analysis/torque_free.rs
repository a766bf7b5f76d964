//! `find precession`: an axisymmetric body under no force (§18.11), stated by its Eulerian
//! angles. The motion is [`torque_free_axisymmetric`]'s, in the symbols I and I′; the body
//! about G gives them (`I = Ī_z`, `I′ = Ī_x = Ī_y`), and the sense is decided from the sign
//! of `I′ − I` ([`precession_sense`]), with the givens' values where the symbols leave it open.

use super::super::model::{EulerAnglesStatement, Span};
use super::{Analyser, Value};
use crate::algebra::four_significant_figures;
use crate::algebra::{Axis, Expr, Func, Symbol};
use crate::mechanics::derivation::{presented, Relation, Step};
use crate::mechanics::gyroscope::{axial_moment, transverse_moment};
use crate::mechanics::torque_free_axisymmetric::{
    precession_sense, torque_free_axisymmetric, Precession,
};
use crate::parse::Diagnostic;

impl Analyser<'_> {
    pub(super) fn torque_free(&mut self, at: Span) -> Result<Value, Diagnostic> {
        let scene = self.scene;
        if scene.euler_angles.is_none() {
            return Err(self.fail(
                at,
                "precession is the torque-free precession of a body stated by its Eulerian angles, and this scene has no 'euler angles'",
                "add 'euler angles' (the frame follows the axis of symmetry z, not the spin)",
            ));
        }
        if !scene.forces.is_empty() || !scene.couples.is_empty() {
            return Err(self.fail(
                at,
                "precession is the motion of a body under no force, and this scene has forces or couples on its body",
                "remove the loads for a body under no force, or ask for the unknowns the loads determine",
            ));
        }
        let inertia = self.body(at)?.inertia.clone();
        let [i_x, i_y, i_z] = inertia.moments.clone();
        let equal = scene.is_exactly_zero(&(&i_x - &i_y));
        if !equal || inertia.products.iter().any(|p| !scene.is_exactly_zero(p)) {
            return Err(self.fail(
                at,
                "precession needs a body axisymmetric about z (I_x = I_y about G, no products of inertia), and this body is not",
                "state the body along z ('body cylinder(r, h) mass m along z')",
            ));
        }
        let (motion, derivation) =
            torque_free_axisymmetric(&EulerAnglesStatement::angles()).map_err(self.algebra(at))?;
        self.plan.extend(derivation.steps);
        let (axial, transverse) = (axial_moment(), transverse_moment());
        let moment = |s: Symbol| {
            (s == axial)
                .then(|| i_z.clone())
                .or_else(|| (s == transverse).then(|| i_x.clone()))
        };
        let in_theta = motion.tan_gamma.subs(&moment).map_err(self.algebra(at))?;
        // θ an unknown (the body stated by ω and γ): its value put in.
        let Value::Scalar(tan_gamma) = self.in_givens(at, Value::Scalar(in_theta.clone()))? else {
            unreachable!("a scalar stays a scalar")
        };
        self.given_gamma_agrees(&tan_gamma)?;
        let gamma = Expr::func(Func::Tan, Expr::symbol("gamma"));
        self.plan.push(Step::new(
            r"this body's moments of inertia about $G$: $I = \bar I_z$, $I' = \bar I_x = \bar I_y$; the sign of $I' - I$ is the sense of the precession",
            vec![
                Relation::new(Expr::sym(axial), i_z.clone(), Axis::Z),
                Relation::new(Expr::sym(transverse), i_x.clone(), Axis::X),
                Relation::new(
                    &Expr::sym(transverse) - &Expr::sym(axial),
                    &i_x - &i_z,
                    Axis::Z,
                ),
                Relation::new(gamma, in_theta, Axis::Z),
            ],
        ));
        let domains = scene.domains();
        // Exact (a defined given too: h = sqrt(3) r makes I' = I exactly, not by round-off).
        let with_values = |e: &Expr| {
            e.subs(&|s| scene.exact_given(s))
                .and_then(|x| x.expand())
                .unwrap_or_else(|_| e.clone())
        };
        let sense = precession_sense(&i_z, &i_x, &domains)
            .or_else(|| precession_sense(&with_values(&i_z), &with_values(&i_x), &domains));
        let Some(sense) = sense else {
            let open: Vec<&str> = (&i_x - &i_z)
                .symbols()
                .into_iter()
                .filter(|s| scene.value(*s).is_none())
                .map(|s| s.name())
                .collect();
            return Err(self.fail(
                at,
                format!(
                    "the sense of the precession is the sign of I' - I = {}, which is not decided without values for {}",
                    presented(&(&i_x - &i_z), &domains),
                    open.join(", ")
                ),
                format!(
                    "give them values, e.g. 'given {} = <number> <unit>'",
                    open.first().copied().unwrap_or("r")
                ),
            ));
        };
        Ok(Value::Precession(Box::new(Precession { tan_gamma, sense })))
    }

    /// A given `gamma` must be the angle this motion has between ω and the axis,
    /// `tan γ = (I/I') tan θ`; a scene that states another (the page would show both) is
    /// refused at that given. Decided with the givens' values, when the two have them. Where
    /// the constraints fixed rates the moment equation contradicts, that deeper cause is the
    /// refusal (the analysis stops here, so the check's derivations need not be shown).
    fn given_gamma_agrees(&mut self, tan_gamma: &Expr) -> Result<(), Diagnostic> {
        let scene = self.scene;
        let Some(given) = scene.givens.iter().find(|g| g.symbol.name() == "gamma") else {
            return Ok(());
        };
        let value = |s: Symbol| scene.value(s);
        let (Some(stated), Ok(derived)) = (given.value, tan_gamma.eval(&value)) else {
            return Ok(());
        };
        // γ in [0°, 180°): the angle of the line of ω from the axis z.
        let derived_angle = derived.atan().rem_euclid(std::f64::consts::PI);
        // The same line through the axis (γ and γ ± π alike), compared as angles: at 90° the
        // tangents are poles.
        if (stated - derived.atan()).sin().abs() <= 1e-9 {
            return Ok(());
        }
        self.motion_obeys_loads()?;
        Err(scene.error_at(
            given.span,
            format!(
                "{} is not the angle between ω and the axis in this motion: under no force tan γ = (I/I') tan θ = {}, so γ = {}°",
                scene.cite(given),
                four_significant_figures(derived),
                four_significant_figures(derived_angle.to_degrees()),
            ),
            "under no force γ follows from θ and the body: drop 'given gamma': find precession derives γ from θ",
        ))
    }
}
