//! Products that read one way only (issue 17, item 4): a thin space beside a name of several
//! letters and after a function's bare argument, a name of several letters never read as a
//! product, a word subscript upright, and two symbols of one page never printed alike.

use kinetics::parse_expression;
use kinetics::print;
use std::process::Command;

fn latex(text: &str) -> String {
    print::latex(&parse_expression("test", text).expect("parses"))
}

#[test]
fn products_read_one_way() {
    for (text, expected) in [
        ("1/2*F_2*Dt*b", r"\frac{1}{2} F_2\,\Delta t\,b"),
        ("6*F*Dt/(m*b)", r"\frac{6 F\,\Delta t}{m b}"),
        ("w^2*sin(beta)*cos(beta)", r"\sin\beta \cos\beta\,\omega^2"),
        ("sin(beta)^2*L*w", r"L \sin^2\beta\,\omega"),
        ("sin(a + b)*L", r"L \sin(a + b)"),
        ("Lb*c", r"\mathit{Lb}\,c"),
        ("L*b", "L b"),
        ("m_body*g", r"m_{\text{body}} g"),
        ("I_xy*w_x", r"I_{xy} \omega_x"),
    ] {
        assert_eq!(latex(text), expected, "{text}");
    }
}

/// The worked solution in LaTeX of a sphere spinning at `omega` (ASCII) with `w_x` given.
fn sphere_spinning_at(omega: &str) -> String {
    sphere_spinning_in("latex", omega)
}

/// The worked solution in `format` of a sphere spinning at `omega` with `w_x` given.
fn sphere_spinning_in(format: &str, omega: &str) -> String {
    let dir = std::env::temp_dir().join(format!("kinetics-spelling-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary folder");
    let scene = dir.join(format!("sphere-{format}-{}.scene", omega.len()));
    std::fs::write(
        &scene,
        format!(
            "given m = 5 kg\ngiven r = 0.1 m\ngiven w_x = 2 rad/s\nbody sphere(r) mass m\n\
             vbar = 0\nomega = {omega}\nfind T\n"
        ),
    )
    .expect("written");
    let run = Command::new(env!("CARGO_BIN_EXE_kinetics"))
        .args(["solve", "--format", format])
        .arg(&scene)
        .output()
        .expect("kinetics runs");
    let _ = std::fs::remove_file(&scene);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    String::from_utf8_lossy(&run.stdout).into_owned()
}

/// A scene that gives `w_x` and derives a different `omega_x = 2 w_x`: the given keeps its
/// letter, `w_x`, and never prints as `\omega_x`, the derived component's name. Where the
/// scene makes them one quantity (`omega = w_x*i`) both are ω_x.
#[test]
fn a_given_w_and_a_derived_omega_print_apart_unless_they_are_one_quantity() {
    let apart = sphere_spinning_at("2*w_x*i");
    // ω stated once as a vector, its component the given w_x, never printed ω_x.
    assert!(
        apart.contains(r"\boldsymbol{\omega} &= 2 w_x \mathbf{i}"),
        "{apart}"
    );
    assert!(!apart.contains(r"\omega_x"), "{apart}");
    assert!(apart.contains(r"$w_x = 2"), "{apart}");
    assert!(apart.contains(r"T &= \frac{4}{5} m r^2 w_x^2"), "{apart}");
    assert!(!apart.contains(r"\omega_x^2"), "{apart}");
    let same = sphere_spinning_at("w_x*i");
    // One quantity: `omega_x = w_x` prints `ω_x = ω_x`, a row that says nothing, left out.
    assert!(!same.contains(r"\omega_x &= \omega_x"), "{same}");
    assert!(
        same.contains(r"T &= \frac{1}{5} m r^2 \omega_x^2"),
        "{same}"
    );
}

/// The HTML page spells a symbol as the LaTeX page does: the given `w_x` beside the derived
/// `omega_x = 2 w_x` is w_x in MathML too, not a second ω_x.
#[test]
fn the_html_page_keeps_the_given_w_apart_as_latex_does() {
    // The base and subscript of `<msub>` (or of `<msubsup>`, under a power).
    let w_x = "<mrow><mi>w</mi></mrow><mrow><mi>x</mi></mrow>";
    let omega_x = "<mrow><mi>ω</mi></mrow><mrow><mi>x</mi></mrow>";
    let apart = sphere_spinning_in("html", "2*w_x*i");
    // Never ω_x (ω is stated as a vector); w_x in the givens, ω's component and T.
    assert_eq!(apart.matches(omega_x).count(), 0, "{apart}");
    assert!(apart.matches(w_x).count() >= 4, "{apart}");
    let same = sphere_spinning_in("html", "w_x*i");
    assert!(!same.contains(w_x), "{same}");
}
