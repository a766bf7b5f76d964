//! `kinetics simulate` of a scene with `euler angles` (issue 19): a heavy top streamed as its
//! Eulerian angles and rates, the turning angles it predicts on standard error and honoured
//! by the run, steady precession kept, the tip's path and θ(t) drawn, and loads other than
//! the weight refused at the load.

use crate::common::binary::kinetics_with_input;

/// A disk of radius r on a light axle, its centre L from the fixed point O, spun at psidot
/// and released at theta with the rates given (disk about O: `I = ½ m r²`,
/// `I′ = ¼ m r² + m L²`).
fn top(theta_deg: f64, steady: bool, extra: &str) -> String {
    let rates = if steady {
        "given phidot = 2 rad/s\ngiven psidot = 200 rad/s\neuler angles steady\n".to_string()
    } else {
        "given thetadot = 0 rad/s\ngiven phidot = 0 rad/s\ngiven psidot = 200 rad/s\n\
         unknown phiddot\nunknown thetaddot\nunknown psiddot\neuler angles\n"
            .to_string()
    };
    format!(
        "title Heavy top\ngiven m = 0.5 kg\ngiven r = 40 mm\ngiven L = 60 mm\n\
         given g = 9.81 m/s^2\ngiven theta = {theta_deg} deg\n{rates}fixed point\n\
         body disk(r) mass m at (0, 0, L) along z\nforce W = -m*g*K at (0, 0, L)\n{extra}"
    )
}

fn rows(csv: &str) -> Vec<Vec<f64>> {
    csv.lines()
        .skip(1)
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect()
}

/// The two angles of `nutation between theta = A and B deg`.
fn predicted(stderr: &str) -> (f64, f64) {
    let line = stderr
        .lines()
        .find(|l| l.starts_with("nutation between theta = "))
        .unwrap_or_else(|| panic!("no prediction in {stderr}"));
    let words: Vec<&str> = line.split_whitespace().collect();
    (words[4].parse().unwrap(), words[6].parse().unwrap())
}

#[test]
fn a_released_top_nutates_between_the_angles_it_prints() {
    // The README's example, the same top as `top(30.0, false, "")`.
    let shipped = format!(
        "{}/examples/simulate/released_top.scene",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&shipped).unwrap();
    let run = kinetics_with_input(
        &["simulate", "-", "--until", "3", "--every", "0.0005"],
        text,
    );
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert_eq!(
        run.stdout.lines().next(),
        Some("t,theta,phi,psi,thetadot,phidot,psidot")
    );
    let (low, high) = predicted(&run.stderr);
    // Released with θ̇ = 0 and no precession, the axis first falls: 30° is the top limit.
    assert!((low - 30.0).abs() < 1e-9, "{low}");
    assert!(high > 31.0, "{high}");
    let theta: Vec<f64> = rows(&run.stdout)
        .iter()
        .map(|r| r[1].to_degrees())
        .collect();
    let (min, max) = theta
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &t| {
            (a.min(t), b.max(t))
        });
    // Sampled every 0.5 ms the extremes are missed by at most θ̈ Δt²/8 ≈ 1e-4 deg.
    assert!(min >= low - 1e-9 && min - low < 1e-3, "{min} against {low}");
    assert!(
        max <= high + 1e-9 && high - max < 1e-3,
        "{max} against {high}"
    );
}

/// The constants of the energy cubic on the prediction's line, in four significant figures
/// and the units as kinetics prints them, each computed here from the givens: released with
/// θ̇ = φ̇ = 0, `E = ½ I ω_z² + m g L cos θ`, `p_φ = I ω_z cos θ`, `ω_z = ψ̇`.
#[test]
fn the_prediction_prints_its_constants_in_four_figures_with_units() {
    let run = kinetics_with_input(
        &["simulate", "-", "--until", "0.1", "--every", "0.01"],
        top(30.0, false, ""),
    );
    assert_eq!(run.code, 0, "{}", run.stderr);
    let (m, r, l, g, theta, spin) = (0.5, 0.04, 0.06, 9.81, 30f64.to_radians(), 200.0);
    let i = 0.5 * m * r * r;
    let energy = 0.5 * i * spin * spin + m * g * l * theta.cos();
    let momentum = i * spin * theta.cos();
    let line = run
        .stderr
        .lines()
        .find(|l| l.starts_with("nutation between theta = "))
        .unwrap_or_else(|| panic!("no prediction in {}", run.stderr));
    let four = kinetics::algebra::four_significant_figures;
    for shown in [
        format!("E = {} J,", four(energy)),
        format!("p_phi = {} kg·m²/s,", four(momentum)),
        format!("omega_z = {} rad/s)", four(spin)),
    ] {
        assert!(line.contains(&shown), "{shown:?} not in {line}");
    }
}

#[test]
fn a_top_in_steady_precession_keeps_theta_and_precesses_at_phidot() {
    // The spin that makes θ = 60° and φ̇ = 2 rad/s steady, from the chapter's condition
    // I′ φ̇² cos θ − I ω_z φ̇ + W c = 0 solved for ω_z, written into the scene as psidot.
    let (m, r, l, g, theta, phidot) = (0.5, 0.04, 0.06, 9.81, 60f64.to_radians(), 2.0);
    let (i, i_t, wc) = (0.5 * m * r * r, 0.25 * m * r * r + m * l * l, m * g * l);
    let spin = (i_t * phidot * phidot * theta.cos() + wc) / (i * phidot);
    let psidot = spin - phidot * theta.cos();
    let scene = top(60.0, true, "").replace(
        "given psidot = 200 rad/s",
        &format!("given psidot = {psidot:.17e} rad/s"),
    );
    let run = kinetics_with_input(&["simulate", "-", "--until", "6", "--rtol", "1e-12"], scene);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let rows = rows(&run.stdout);
    for row in &rows {
        assert!(((row[1] - theta) / theta).abs() < 1e-9, "{row:?}");
        assert!(((row[5] - phidot) / phidot).abs() < 1e-9, "{row:?}");
        assert!((row[2] - phidot * row[0]).abs() < 1e-8, "φ at {row:?}");
    }
    let (low, high) = predicted(&run.stderr);
    assert!((low - 60.0).abs() < 1e-7 && (high - 60.0).abs() < 1e-7);
}

#[cfg(feature = "plot")]
#[test]
fn the_plot_shows_the_axis_from_above_beside_theta() {
    let path = std::env::temp_dir().join(format!("kinetics-top-{}.svg", std::process::id()));
    let _ = std::fs::remove_file(&path);
    let run = kinetics_with_input(
        &[
            "simulate",
            "-",
            "--until",
            "2",
            "--plot",
            path.to_str().unwrap(),
        ],
        top(30.0, false, ""),
    );
    assert_eq!(run.code, 0, "{}", run.stderr);
    let svg = std::fs::read_to_string(&path).unwrap();
    std::fs::remove_file(&path).unwrap();
    assert!(svg.contains("the axis seen from above"), "{svg}");
    assert!(svg.contains("nutation"));
    // The legend covers no data: each name and each sample of a line (a coloured stroke of
    // two points) lies outside the box of every line of data (a coloured stroke of more).
    let (data, samples): (Vec<Line>, Vec<Line>) = coloured_polylines(&svg)
        .into_iter()
        .partition(|p| p.len() > 2);
    assert_eq!((data.len(), samples.len()), (2, 2), "{svg}");
    let boxes: Vec<[f64; 4]> = data.iter().map(|p| bounding_box(p)).collect();
    let names = ["tip of the axis", "θ"].map(|name| text_anchor(&svg, name));
    for point in samples.iter().flatten().chain(&names) {
        for b in &boxes {
            let inside = (b[0]..=b[1]).contains(&point.0) && (b[2]..=b[3]).contains(&point.1);
            assert!(!inside, "the legend at {point:?} covers the data in {b:?}");
        }
    }
    // The tip's path is drawn undistorted: as many pixels per unit across as up, the path's
    // extent in pixels against its extent from the samples, X = sin θ sin φ, Y = −sin θ cos φ.
    let tip: Vec<(f64, f64)> = rows(&run.stdout)
        .iter()
        .map(|r| (r[1].sin() * r[2].sin(), -r[1].sin() * r[2].cos()))
        .collect();
    let (pixels, units) = (bounding_box(&data[0]), bounding_box(&tip));
    let across = (pixels[1] - pixels[0]) / (units[1] - units[0]);
    let up = (pixels[3] - pixels[2]) / (units[3] - units[2]);
    assert!(
        (across / up - 1.0).abs() < 0.01,
        "{across} pixels per unit across, {up} up"
    );
}

/// A line of an SVG, its points in pixels.
#[cfg(feature = "plot")]
type Line = Vec<(f64, f64)>;

#[cfg(feature = "plot")]
/// The points of each `<polyline>` drawn in a colour (not the black of the axes).
fn coloured_polylines(svg: &str) -> Vec<Line> {
    svg.split("<polyline")
        .skip(1)
        .map(|p| p.split("/>").next().unwrap())
        .filter(|p| !p.contains(r##"stroke="#000000""##))
        .map(|p| {
            let points = p
                .split(r#"points=""#)
                .nth(1)
                .unwrap()
                .split('"')
                .next()
                .unwrap();
            points
                .split_whitespace()
                .map(|xy| {
                    let (x, y) = xy.split_once(',').unwrap();
                    (x.parse().unwrap(), y.parse().unwrap())
                })
                .collect()
        })
        .collect()
}

#[cfg(feature = "plot")]
/// `[x_min, x_max, y_min, y_max]` of the points.
fn bounding_box(points: &[(f64, f64)]) -> [f64; 4] {
    points.iter().fold(
        [
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ],
        |b, &(x, y)| [b[0].min(x), b[1].max(x), b[2].min(y), b[3].max(y)],
    )
}

#[cfg(feature = "plot")]
/// Where the `<text>` whose content is exactly `name` is anchored.
fn text_anchor(svg: &str, name: &str) -> (f64, f64) {
    let element = svg
        .split("<text")
        .skip(1)
        .find(|t| {
            t.split_once('>')
                .map(|(_, rest)| rest.trim_start())
                .is_some_and(|c| c.starts_with(&format!("{name}\n")))
        })
        .unwrap_or_else(|| panic!("no text {name:?} in {svg}"));
    let attribute = |a: &str| -> f64 {
        element
            .split(&format!(" {a}=\""))
            .nth(1)
            .unwrap()
            .split('"')
            .next()
            .unwrap()
            .parse()
            .unwrap()
    };
    (attribute("x"), attribute("y"))
}

#[test]
fn a_load_other_than_the_weight_is_refused_at_the_load() {
    let run = kinetics_with_input(
        &["simulate", "-", "--until", "1"],
        top(30.0, false, "given M = 0.1 N*m\ncouple M*k\n"),
    );
    assert_eq!(run.code, 1);
    assert!(run.stdout.is_empty());
    assert!(
        run.stderr
            .contains("the simulation of a top takes the moment of its weight only"),
        "{}",
        run.stderr
    );
    // Blamed on the couple (line 18 of the scene), not on the weight before it.
    assert!(run.stderr.contains(":18:"), "{}", run.stderr);
}
