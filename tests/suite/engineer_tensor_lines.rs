//! The engineer's lines of a tensor and of a principal frame (`solve --numbers`, and the
//! Answers block of `solve`): a tensor as its rows, a frame as its labelled moments with
//! their unit and its axes without one, never a flat list of twelve numbers under kg·m².
//! Checked on `examples/scenes/box_about_body_diagonal.scene` (m = 6 kg, a = 0.3 m,
//! b = 0.2 m, c = 0.1 m) against the hand's [I_G] = diag(b² + c², c² + a², a² + b²) m/12,
//! whose principal axes are x, y, z.

use crate::common::binary::{kinetics, scene};

fn line<'a>(out: &'a str, block: &str, start: &str) -> &'a str {
    let block = out
        .split(&format!("\n{block}\n"))
        .nth(1)
        .expect("the block");
    block
        .lines()
        .find(|l| l.trim_start().starts_with(start))
        .unwrap_or_else(|| panic!("no line {start} in:\n{out}"))
        .trim()
}

#[test]
fn a_tensor_is_its_rows_and_a_frame_its_labelled_moments_and_axes() {
    let (m, a, b, c): (f64, f64, f64, f64) = (6.0, 0.3, 0.2, 0.1);
    let moments = [b * b + c * c, c * c + a * a, a * a + b * b].map(|s| m * s / 12.0);
    let f = |x: f64| format!("{}", (x * 1e4).round() / 1e4);
    let tensor = format!(
        "I_G = [[{}, 0, 0], [0, {}, 0], [0, 0, {}]] kg·m²",
        f(moments[0]),
        f(moments[1]),
        f(moments[2])
    );
    // A frame's rows under its name: the moments with their unit, the axes (exact: x, y, z)
    // without one.
    let frame = format!(
        "  principal_G:\n    I_1 = {} kg·m²\n    I_2 = {} kg·m²\n    I_3 = {} kg·m²\n    \
         e_1 = i\n    e_2 = j\n    e_3 = k\n",
        f(moments[0]),
        f(moments[1]),
        f(moments[2])
    );
    let path = scene("box_about_body_diagonal");
    for (args, block) in [
        (vec!["solve", "--numbers"], "Results"),
        (vec!["solve"], "Answers"),
    ] {
        let args: Vec<&str> = args.into_iter().chain([path.as_str()]).collect();
        let (code, out, err) = kinetics(&args);
        assert_eq!(code, 0, "{err}");
        assert_eq!(line(&out, block, "I_G = "), tensor);
        assert!(out.contains(&frame), "{out}");
        // The numeric frame about O: its axes carry no unit.
        let axis = line(&out, block, "e_1 = 0.");
        assert!(!axis.contains("kg·m²"), "{axis}");
    }
}
