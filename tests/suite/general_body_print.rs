//! Pins the printed output of the benchmarked general-body pipeline (`H = [I]ω`,
//! `T = ½ωᵀ[I]ω`, `[I]α + ω × ([I]ω)`), in LaTeX and in text, so that work on the speed of
//! the algebra and the printers cannot change a byte of what is printed.

use kinetics::print;

#[path = "../../benches/support/general_body.rs"]
mod general_body;

#[test]
fn general_body_latex() {
    insta::assert_snapshot!(general_body::pipeline().join("\n"));
}

#[test]
fn general_body_text() {
    let c = general_body::canonical(&general_body::build());
    let mut lines: Vec<String> = c.h.iter().map(print::text).collect();
    lines.push(print::text(&c.t));
    lines.extend(
        c.euler
            .iter()
            .zip(general_body::AXES)
            .map(|(m, axis)| print::text_about(m, axis)),
    );
    insta::assert_snapshot!(lines.join("\n"));
}

#[test]
fn text_reads_back_to_the_same_expressions() {
    let c = general_body::canonical(&general_body::build());
    for e in c.h.iter().chain([&c.t]).chain(c.euler.iter()) {
        let printed = print::text(e);
        let parsed =
            kinetics::parse::parse_expression("printed", &printed).expect("printed text parses");
        assert_eq!(parsed.expand().unwrap(), *e, "{printed}");
    }
}
