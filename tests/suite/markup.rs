//! Step titles: words with mathematics between `$…$` in a LaTeX subset
//! (`kinetics::print::markup`), rendered as text, LaTeX, Markdown and MathML. Every title the
//! program produces is well formed, reads as plain text without markup, and compiles.

use kinetics::print::markup;

const HDOT: &str = r"rate relative to the rotating frame, $(\dot{\mathbf{H}}_G)_{Gxyz} = [I]\{\dot{\boldsymbol{\omega}}\}$";

#[test]
fn text_drops_the_markup() {
    let cases = [
        (
            HDOT,
            "rate relative to the rotating frame, (Ḣ_G)_Gxyz = [I]{ω̇}",
        ),
        (r"$\Sigma\mathbf{F} = m\bar{\mathbf{a}}$", "ΣF = mā"),
        (r"positive, $\int xy\,dm$", "positive, ∫xy dm"),
        (
            r"$T = \frac12 m\bar{v}^2 + \tfrac{1}{2}\{\omega\}^T[I]\{\omega\}$",
            "T = ½ mv̄² + ½{ω}ᵀ[I]{ω}",
        ),
        (r"$(\dot{\boldsymbol{\omega}})_{\text{frame}}$", "(ω̇)_frame"),
        (r"$\Sigma M_x = -l B_y$, $2^\circ$", "ΣM_x = -l B_y, 2°"),
        (r"$\bar{\mathbf{v}}_1 \neq \bar{\mathbf{v}}_2$", "v̄₁ ≠ v̄₂"),
        (r"$\frac{a + b}{2 m}$", "(a + b)/(2 m)"),
        (r"$x^{n+1}$, $I_{xy} = I_{yz} = 0$", "xⁿ⁺¹, I_xy = I_yz = 0"),
        (
            r"$\mathbf{H}_O = \mathbf{H}_G + \bar{\mathbf{r}} \times m\bar{\mathbf{v}}$",
            "H_O = H_G + r̄ × mv̄",
        ),
    ];
    for (title, text) in cases {
        assert_eq!(markup::text(title), text, "{title}");
    }
}

#[test]
fn latex_escapes_words_and_normalises_maths() {
    let cases = [
        (
            HDOT,
            r"rate relative to the rotating frame, $(\dot{\mathbf{H}}_G)_{Gxyz} = [I]\{\dot{\boldsymbol{\omega}}\}$",
        ),
        (
            r"50% of I_xy & #1 {x} ^ ~ \ ",
            r"50\% of I\_xy \& \#1 \{x\} \^{} \~{} \textbackslash{} ",
        ),
        (r"$\tfrac12 \omega x$", r"$\tfrac{1}{2} \omega x$"),
        (r"$\omega\,x$, $\omega{x}$", r"$\omega\,x$, $\omega{x}$"),
        ("$ x × y $", r"$x \times y$"),
        (
            r"$2^\circ$, $m_{\text{body}}$",
            r"$2^{\circ}$, $m_{\text{body}}$",
        ),
        (
            "Ω = ω, ω̇ and r̄",
            r"$\Omega$ = $\omega$, $\dot{\omega}$ and $\bar{r}$",
        ),
        ("ΣΔ", r"$\Sigma\Delta$"),
        ("empty $$ maths", "empty  maths"),
    ];
    for (title, latex) in cases {
        assert_eq!(markup::latex(title), latex, "{title}");
    }
}

#[test]
fn markdown_escapes_its_marks() {
    assert_eq!(
        markup::markdown(r"about *O*, [I_O] $\mathbf{H}_O$"),
        r"about \*O\*, \[I\_O\] $\mathbf{H}_O$"
    );
}

#[test]
fn html_writes_mathml_core() {
    assert_eq!(
        markup::html(r"a < b: $\dot{\mathbf{H}}_G$"),
        "a &lt; b: <math><msub><mrow><mover accent=\"true\"><mrow><mrow>\
         <mi mathvariant=\"bold\">𝐇</mi></mrow></mrow><mo>\u{2d9}</mo></mover></mrow>\
         <mrow><mi>G</mi></mrow></msub></math>"
    );
    assert_eq!(
        markup::html(r"$\Sigma M - \frac{1}{2}\,\text{x}$"),
        "<math><mi mathvariant=\"normal\">Σ</mi><mi>M</mi><mo>−</mo><mfrac><mrow><mn>1</mn>\
         </mrow><mrow><mn>2</mn></mrow></mfrac><mspace width=\"0.1667em\"/><mtext>x</mtext></math>"
    );
    assert_eq!(
        markup::html(r"$\bar{\boldsymbol{\omega}}^2$"),
        "<math><msup><mrow><mover accent=\"true\"><mrow><mrow><mi mathvariant=\"bold\">𝝎</mi>\
         </mrow></mrow><mo>\u{af}</mo></mover></mrow><mrow><mn>2</mn></mrow></msup></math>"
    );
}

#[test]
fn a_malformed_title_is_words_and_validate_says_why() {
    for (title, offset, why) in [
        (r"bad $\foo x$", 5, "unknown command"),
        ("bad $x", 4, "never closed"),
        ("bad $x_{1$", 7, "brace"),
        (r"bad $\frac{1}$", 13, "missing"),
        ("bad $x ; y$", 7, "not in the mathematics"),
    ] {
        let error = markup::validate(title).expect_err(title);
        assert_eq!(error.offset, offset, "{title}: {error}");
        assert!(error.to_string().contains(why), "{title}: {error}");
        assert_eq!(markup::text(title), title);
        assert!(
            !markup::latex(title).contains(" $"),
            "{}",
            markup::latex(title)
        );
        assert!(markup::html(title).starts_with("bad "));
    }
    for hostile in [
        "{{{{",
        "$}}}}$",
        "$^^^$",
        "$\\",
        "$\\\u{e9}$",
        "$_{$",
        "\u{0307}$\u{0307}$",
    ] {
        let _ = (
            markup::text(hostile),
            markup::latex(hostile),
            markup::html(hostile),
        );
        let _ = markup::markdown(hostile);
    }
    let deep = format!("${}x{}$", "{".repeat(10_000), "}".repeat(10_000));
    assert!(markup::validate(&deep).is_err());
    assert_eq!(markup::text(&deep), deep);
}

/// Every step and derivation title the program produces: `derive`'s catalogue (general and
/// principal, and each derivation's convention) and the plan of every example scene.
fn every_title() -> Vec<String> {
    use kinetics::algebra::Axis;
    use kinetics::mechanics::catalogue::{convention, derive_general, NAMES};
    let mut titles = Vec::new();
    for axis in [Axis::X, Axis::Y, Axis::Z] {
        titles.extend(NAMES.iter().filter_map(|name| convention(name, axis)));
    }
    for principal in [false, true] {
        for name in NAMES {
            let d = derive_general(name, principal)
                .expect("a known name")
                .expect("derives");
            titles.push(d.title.clone());
            titles.extend(d.steps.iter().map(|s| s.title.clone()));
        }
    }
    let scenes = crate::common::examples::example_scenes();
    for path in scenes {
        let source = std::fs::read_to_string(&path).expect("readable");
        let scene = kinetics::parse_scene(&path.display().to_string(), &source).expect("parses");
        let analysis = kinetics::analyse(&scene).expect("analyses");
        titles.extend(scene.title.clone());
        titles.extend(analysis.plan.iter().map(|s| s.title.clone()));
    }
    titles.sort();
    titles.dedup();
    titles
}

#[test]
fn every_title_the_program_produces_is_well_formed_and_reads_as_text() {
    let titles = every_title();
    assert!(titles.len() > 20, "{titles:?}");
    for title in &titles {
        if let Err(e) = markup::validate(title) {
            panic!("{title}: {e}");
        }
        let text = markup::text(title);
        assert!(
            !text.contains(['$', '\\']) && !text.contains("_{"),
            "{title} reads {text}"
        );
    }
}

#[test]
fn a_document_of_every_title_compiles_with_pdflatex() {
    let dir = std::env::temp_dir().join(format!("kinetics-markup-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary folder");
    let mut tex =
        String::from("\\documentclass{article}\n\\usepackage{amsmath}\n\\begin{document}\n");
    for title in every_title() {
        tex.push_str(&format!(
            "\\paragraph{{Step}} {}\n\n",
            markup::latex(&title)
        ));
    }
    // Words that LaTeX would read as commands, and a malformed title shown as words.
    tex.push_str(&markup::latex(r"50% of I_xy & #1 {x} ^ ~ \ ω̇ r̄ ΣΔ $\foo$"));
    tex.push_str("\n\\end{document}\n");
    let file = dir.join("titles.tex");
    std::fs::write(&file, &tex).expect("written");
    let compiled = crate::common::pdflatex::pdflatex(&dir, &file);
    let _ = std::fs::remove_dir_all(&dir);
    if let Some(error) = compiled.first_error() {
        panic!("{tex}\n{error}");
    }
}

/// Every title's HTML is well formed, and each MathML element that takes a fixed number of
/// children has them: two for `msub`, `msup`, `mfrac`, `mover`, three for `msubsup`.
#[test]
fn every_title_is_well_formed_mathml() {
    for title in every_title() {
        let html = markup::html(&title);
        // (tag, children so far) of each open element.
        let mut open: Vec<(String, usize)> = Vec::new();
        let mut rest = html.as_str();
        while let Some(start) = rest.find('<') {
            let end = rest[start..].find('>').expect("a tag closes") + start;
            let tag = &rest[start + 1..end];
            rest = &rest[end + 1..];
            if let Some(name) = tag.strip_prefix('/') {
                let (opened, children) = open.pop().expect("an element to close");
                assert_eq!(opened, name, "{html}");
                let expected = match name {
                    "msub" | "msup" | "mfrac" | "mover" => Some(2),
                    "msubsup" => Some(3),
                    _ => None,
                };
                assert!(expected.is_none_or(|n| n == children), "<{name}> in {html}");
                continue;
            }
            if let Some(parent) = open.last_mut() {
                parent.1 += 1;
            }
            if !tag.ends_with('/') {
                let name = tag.split(' ').next().unwrap_or_default().to_string();
                open.push((name, 0));
            }
        }
        assert!(open.is_empty(), "{html}");
        assert_eq!(
            html.matches("<math>").count(),
            title.matches('$').count() / 2,
            "{title}"
        );
    }
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(512))]

    /// Any title, however malformed, renders in every notation without a panic; a title
    /// that validates reads as text without a `$`, a malformed one as itself.
    #[test]
    fn any_title_renders(title in r"[a-zA-Z0-9 $\\{}_^+=×()\[\],./|'ω̇¯%&#~-]{0,40}|[$\\a-z{}_^ ]{0,40}") {
        let text = markup::text(&title);
        let (_, _, _) = (markup::latex(&title), markup::markdown(&title), markup::html(&title));
        if markup::validate(&title).is_ok() {
            proptest::prop_assert!(!text.contains('$'), "{} reads {}", title, text);
        } else {
            proptest::prop_assert_eq!(text, title);
        }
    }
}
