//! `kinetics mark`: the example class (examples/marking/) marked, its gradebook against marks
//! worked out by hand here, its summary's top slip per question against the planted ones,
//! and a submissions file with bad rows marking every other answer.

use crate::common::binary::kinetics;
use std::collections::HashMap;
use std::path::{Path, PathBuf};

/// A fresh directory for one test's output, removed when dropped.
struct OutputDir(PathBuf);

impl OutputDir {
    fn new(name: &str) -> OutputDir {
        let dir = std::env::temp_dir().join(format!("kinetics-mark-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        OutputDir(dir)
    }
    fn path(&self) -> &str {
        self.0.to_str().expect("a UTF-8 temporary path")
    }
    /// Writes `file` in the folder (made if need be) and returns its path.
    fn write(&self, file: &str, contents: impl AsRef<[u8]>) -> PathBuf {
        std::fs::create_dir_all(&self.0).expect("created");
        let path = self.0.join(file);
        std::fs::write(&path, contents).expect("written");
        path
    }
    fn read(&self, file: &str) -> String {
        std::fs::read_to_string(self.0.join(file)).unwrap_or_else(|e| panic!("{file}: {e}"))
    }
}

impl Drop for OutputDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// `kinetics mark SCHEME SUBMISSIONS -o OUT`.
fn mark(scheme: &Path, submissions: &Path, out: &Path) -> (i32, String, String) {
    let path = |p: &Path| p.to_str().expect("a UTF-8 temporary path").to_owned();
    kinetics(&["mark", &path(scheme), &path(submissions), "-o", &path(out)])
}

fn example(file: &str) -> String {
    format!("{}/examples/marking/{file}", env!("CARGO_MANIFEST_DIR"))
}

/// Each answer of the example class, with its marks worked out by hand and the slip it plants
/// (`-` where it has none). Steps share a question's marks; a step right only from an earlier
/// slip gets the scheme's carried_forward (0.5) of its marks.
const ANSWERS: [(&str, &str, f64, &str); 23] = [
    // Q1 (SP 18.4), steps Ḣ_z and D_y of 2 marks each. The truth: Ḣ_z = −I_xz α − I_xy ω²,
    // L D_y = Ḣ_z, D_y = −3M/(16c) − ¼ m c ω² = −129.8 N.
    ("Q1", "Hdot_z = -I_xz alpha - I_xy w^2\nD_y L = Hdot_z\nD_y = -3 M/(16 c) - 1/4 m c w^2", 4.0, "-"),
    // The moment of D_y about C written −L D_y: Ḣ_z right (2); D_y = +3M/(16c) + ¼ m c ω²
    // is line 2 divided by −L, carried (1).
    ("Q1", "Hdot_z = -I_xz alpha - I_xy w^2\n-D_y L = Hdot_z\nD_y = 3 M/(16 c) + 1/4 m c w^2", 3.0, "scaled"),
    // Ω × H_C dropped: Ḣ_z = −I_xz α wrong (0); D_y = −3M/(16c) from it, carried (1).
    ("Q1", "Hdot_z = -I_xz alpha\nD_y L = Hdot_z\nD_y = -3 M/(16 c)", 1.0, "transport-term-missing"),
    // I_xz α with a plus: wrong (0); D_y = (I_xz α − I_xy ω²)/L = 3M/(16c) − ¼ m c ω², carried (1).
    ("Q1", "Hdot_z = I_xz alpha - I_xy w^2\nD_y L = Hdot_z\nD_y = 3 M/(16 c) - 1/4 m c w^2", 1.0, "sign-flipped"),
    // Only the number: D_y right (2), no line gives Ḣ_z (0).
    ("Q1", "D_y = -129.8 N", 2.0, "a quantity asked for is not given"),
    // A bare number is the value of the last quantity, D_y.
    ("Q1", "-129.8 N", 2.0, "a quantity asked for is not given"),
    // Ḣ_z right (2); ¼ m c ω² with the wrong sign in D_y, its own slip (0).
    ("Q1", "Hdot_z = -I_xz alpha - I_xy w^2\nD_y = -3 M/(16 c) + 1/4 m c w^2", 2.0, "cross-product-reversed"),
    // Q2 (SP 18.2), T of 2 marks: T = ⅛ m r² (6 + r²/L²) ω₁².
    ("Q2", "T = 1/8 m r^2 (6 + r^2/L^2) w1^2", 2.0, "-"),
    ("Q2", "T = 1/4 m r^2 (6 + r^2/L^2) w1^2", 0.0, "half-missing"),
    // ¼ m r² about a diameter without m L²: ⅛ m r² (2 + r²/L²) ω₁².
    ("Q2", "T = 1/8 m r^2 (2 + r^2/L^2) w1^2", 0.0, "parallel-axis-missing"),
    // ¼ and ½ exchanged: ⅛ m r² (5 + 2r²/L²) ω₁².
    ("Q2", "T = 1/8 m r^2 (5 + 2 r^2/L^2) w1^2", 0.0, "wrong-moment-of-inertia"),
    // ω₂ inverted (L ω₁/r for r ω₁/L); T in ω₂ holds, T with the inverted ω₂ put in carries it (1).
    ("Q2", "w2 = L w1 / r\nT = 1/2 (1/2 m r^2 w1^2 + (m L^2 + 1/4 m r^2) w2^2)\nT = 1/4 m r^2 w1^2 + 1/2 (m L^2 + 1/4 m r^2) L^2 w1^2/r^2", 1.0, "differs (no reading fits)"),
    // A parenthesis left open: the line cannot be read (0).
    ("Q2", "T = 1/8 m r^2 (6 + r^2/L^2 w1^2", 0.0, "a line could not be read"),
    // Through I_x, I_y about O and ω₂: T = ½(I_x ω₁² + I_y ω₂²) holds (2).
    ("Q2", "I_x = 1/2 m r^2\nI_y = m L^2 + 1/4 m r^2\nw2 = r w1 / L\nT = 1/2 (I_x w1^2 + I_y w2^2)", 2.0, "-"),
    // Q3 (principal axes), ΣM_x of 2 marks: I_x ω̇_x − (I_y − I_z) ω_y ω_z.
    ("Q3", "SumM_x = I_x wdot_x - (I_y - I_z) w_y w_z", 2.0, "-"),
    ("Q3", "H_y = I_y w_y\nH_z = I_z w_z\nSumM_x = I_x wdot_x + w_y H_z - w_z H_y", 2.0, "-"),
    ("Q3", "SumM_x = I_x wdot_x + (I_y - I_z) w_y w_z", 0.0, "cross-product-reversed"),
    ("Q3", "SumM_x = I_x wdot_x", 0.0, "transport-term-missing"),
    // H_z = I_y ω_z (subscripts swapped); ΣM_x = I_x ω̇_x + ω_y H_z − ω_z H_y holds; with the
    // wrong H_z it is I_x ω̇_x, carried (1).
    ("Q3", "H_z = I_y w_z\nSumM_x = I_x wdot_x + w_y H_z - w_z H_y\nSumM_x = I_x wdot_x", 1.0, "swapped-subscripts"),
    // Q4 (SP 18.5), N of 2 marks: N = W + m r³ ω₁²/(2L²).
    ("Q4", "N = W + m r^3 w_1^2/(2 L^2)", 2.0, "-"),
    ("Q4", "N = W", 0.0, "transport-term-missing"),
    // Ω taken as the whole ω: an extra −m r ω₁² and the moment halved.
    ("Q4", "N = W - m r w_1^2 + m r^3 w_1^2/(4 L^2)", 0.0, "omega-for-Omega"),
    // ¼ m r² about the axle for ½: the gyroscopic moment halved.
    ("Q4", "N = W + m r^3 w_1^2/(4 L^2)", 0.0, "wrong-moment-of-inertia"),
];

/// The marks of an answer not in [`ANSWERS`] are a failure of the test's table.
fn hand_marks(question: &str, answer: &str) -> f64 {
    ANSWERS
        .iter()
        .find(|(q, a, _, _)| *q == question && *a == answer)
        .map(|(_, _, marks, _)| *marks)
        .unwrap_or_else(|| panic!("{question}: no hand marks for {answer:?}"))
}

/// The example's rows: (student, question, answer).
fn rows(path: &str) -> Vec<(String, String, String)> {
    let mut reader = csv::Reader::from_path(path).expect("the example's submissions");
    reader
        .records()
        .map(|r| {
            let r = r.expect("a row");
            (r[0].to_string(), r[1].to_string(), r[2].to_string())
        })
        .collect()
}

#[test]
fn the_example_class_gets_the_marks_worked_out_by_hand() {
    let out = OutputDir::new("example");
    let (code, stdout, stderr) = kinetics(&[
        "mark",
        &example("scheme.toml"),
        &example("submissions.csv"),
        "-o",
        out.path(),
    ]);
    assert_eq!(code, 0, "{stdout}\n{stderr}");
    // The hand marks of each student's answers; a question without a row is 0.
    let mut expected: Vec<(String, [f64; 4])> = Vec::new();
    for (student, question, answer) in rows(&example("submissions.csv")) {
        let q = ["Q1", "Q2", "Q3", "Q4"]
            .iter()
            .position(|id| *id == question)
            .expect("a question of the scheme");
        if !expected.iter().any(|(s, _)| *s == student) {
            expected.push((student.clone(), [0.0; 4]));
        }
        let row = expected
            .iter_mut()
            .find(|(s, _)| *s == student)
            .expect("added");
        row.1[q] = hand_marks(&question, &answer);
    }
    assert_eq!(expected.len(), 30, "the example has 30 students");
    let grades = out.read("grades.csv");
    let mut lines = grades.lines();
    assert_eq!(lines.next(), Some("student,Q1,Q2,Q3,Q4,total"));
    for ((student, marks), line) in expected.iter().zip(lines) {
        let total: f64 = marks.iter().sum();
        let row: Vec<String> = std::iter::once(student.clone())
            .chain(marks.iter().chain([&total]).map(|m| format!("{m}")))
            .collect();
        assert_eq!(line, row.join(","), "{student}");
    }
    // Every student has a feedback page in both notations.
    for (student, _) in &expected {
        for ext in ["md", "html"] {
            assert!(
                out.0.join(format!("feedback/{student}.{ext}")).exists(),
                "{student}.{ext}"
            );
        }
    }
}

/// The slips of the summary's tables, in order, per question (`## Q1` headings).
fn summary_slips(summary: &str) -> HashMap<String, Vec<(String, usize)>> {
    let mut slips: HashMap<String, Vec<(String, usize)>> = HashMap::new();
    let mut question = String::new();
    for line in summary.lines() {
        if let Some(heading) = line.strip_prefix("## ") {
            question = heading.split(' ').next().unwrap_or_default().to_string();
        } else if let Some(row) = line.strip_prefix("| **") {
            let (slip, rest) = row.split_once("** | ").expect("a slip row");
            // `6 (20 %) | …`: the count before its share.
            let count = rest
                .split(' ')
                .next()
                .and_then(|c| c.parse().ok())
                .expect("a count");
            slips
                .entry(question.clone())
                .or_default()
                .push((slip.to_string(), count));
        }
    }
    slips
}

#[test]
fn the_summary_ranks_the_planted_slips_first() {
    let out = OutputDir::new("summary");
    let (code, _, stderr) = kinetics(&[
        "mark",
        &example("scheme.toml"),
        &example("submissions.csv"),
        "-o",
        out.path(),
    ]);
    assert_eq!(code, 0, "{stderr}");
    // The slip each question's answers plant most often (submissions.csv: 6 moment signs in
    // Q1, 5 halves in Q2, 6 reversed cross products in Q3, 5 ω for Ω in Q4), with how many
    // students each, counted from the rows against the hand table.
    let mut planted: HashMap<(String, String), usize> = HashMap::new();
    let mut answered: HashMap<String, usize> = HashMap::new();
    for (_, question, answer) in rows(&example("submissions.csv")) {
        let (_, _, _, slip) = ANSWERS
            .iter()
            .find(|(q, a, _, _)| *q == question && *a == answer)
            .expect("a hand-marked answer");
        *answered.entry(question.clone()).or_default() += 1;
        if *slip != "-" {
            *planted.entry((question, slip.to_string())).or_default() += 1;
        }
    }
    let slips = summary_slips(&out.read("summary.md"));
    for (question, top) in [
        ("Q1", "scaled"),
        ("Q2", "half-missing"),
        ("Q3", "cross-product-reversed"),
        ("Q4", "omega-for-Omega"),
    ] {
        let ranked = &slips[question];
        assert_eq!(ranked[0].0, top, "{question}: {ranked:?}");
        for (slip, count) in ranked {
            let expected = match slip.as_str() {
                "no answer marked" => 30 - answered[question],
                _ => planted[&(question.to_string(), slip.clone())],
            };
            assert_eq!(*count, expected, "{question}: {slip}");
        }
    }
}

#[test]
fn bad_rows_are_named_and_every_other_answer_is_marked() {
    let out = OutputDir::new("bad-rows");
    let submissions = out.0.with_extension("csv");
    // Line 2 and 3 good; line 4 a broken row (4 fields); line 5 an unknown question; line 6
    // a non-UTF-8 byte in an answer; line 7 an answer that cannot be read; bea answers only Q1.
    let mut bytes = b"student,question,answer\n\
ana,Q3,SumM_x = I_x wdot_x - (I_y - I_z) w_y w_z\n\
ana,Q4,N = W + m r^3 w_1^2/(2 L^2)\n\
bea,Q3,SumM_x = I_x wdot_x,extra\n\
bea,Q9,N = W\n"
        .to_vec();
    bytes.extend_from_slice(b"cruz,Q3,SumM_x = I_x wdot_x \xff\n");
    bytes.extend_from_slice(b"cruz,Q4,N = = W\n");
    bytes.extend_from_slice(b"bea,Q1,-129.8 N\n");
    std::fs::write(&submissions, &bytes).expect("written");
    let path = submissions.to_str().expect("UTF-8");
    let (code, stdout, stderr) =
        kinetics(&["mark", &example("scheme.toml"), path, "-o", out.path()]);
    let _ = std::fs::remove_file(&submissions);
    assert_eq!(code, 0, "{stdout}\n{stderr}");
    for (line, who) in [
        (4, "bea, Q3"),
        (5, "bea, Q9"),
        (6, "cruz, Q3"),
        (7, "cruz, Q4"),
    ] {
        assert!(
            stderr.contains(&format!("{path}:{line}: {who}: ")),
            "line {line} named: {stderr}"
        );
    }
    assert!(stderr.contains("is not UTF-8"), "{stderr}");
    assert!(stderr.contains("no question \"Q9\""), "{stderr}");
    // ana: Q3 and Q4 right (2 + 2); bea: Q1's bare −129.8 N gives D_y (2 of 4), Q3's row
    // broken (0); cruz: both rows unmarked (0).
    assert_eq!(
        out.read("grades.csv"),
        "student,Q1,Q2,Q3,Q4,total\nana,0,0,2,2,4\nbea,2,0,0,0,2\ncruz,0,0,0,0,0\n"
    );
    let bea = out.read("feedback/bea.md");
    assert!(
        bea.contains("could not be marked: the row has 4 fields"),
        "{bea}"
    );
    assert!(bea.contains("No answer"), "bea has no row for Q2: {bea}");
    assert!(out.read("summary.md").contains("Rows not marked"));
}

#[test]
fn an_earlier_run_is_not_overwritten_without_force() {
    let out = OutputDir::new("force");
    let args = |force: bool| {
        let mut a = vec![
            "mark".to_string(),
            example("scheme.toml"),
            example("submissions.csv"),
        ];
        a.extend(["-o".to_string(), out.path().to_string()]);
        if force {
            a.push("--force".into());
        }
        a
    };
    let run = |a: Vec<String>| kinetics(&a.iter().map(String::as_str).collect::<Vec<_>>());
    assert_eq!(run(args(false)).0, 0);
    let (code, _, stderr) = run(args(false));
    assert_eq!(code, 1);
    assert!(
        stderr.contains("grades.csv exists") && stderr.contains("--force"),
        "{stderr}"
    );
    assert_eq!(run(args(true)).0, 0);
}

#[test]
fn a_scheme_naming_an_unknown_slip_is_refused_where_it_names_it() {
    let dir = OutputDir::new("scheme");
    let scheme = dir.write(
        "scheme.toml",
        "[[question]]\nid = \"Q1\"\ncontext = \"principal\"\ngives = \"SumM_x\"\nmarks = 2\n\
         [question.feedback]\nsign-flip = \"Check the signs.\"\n",
    );
    let (code, _, stderr) = kinetics(&[
        "mark",
        scheme.to_str().expect("UTF-8"),
        &example("submissions.csv"),
        "-o",
        &dir.0.join("out").to_string_lossy(),
    ]);
    assert_eq!(code, 1);
    assert!(
        stderr.contains("no slip is named \"sign-flip\""),
        "{stderr}"
    );
    assert!(
        stderr.contains(":7:"),
        "the error stands at line 7: {stderr}"
    );
    assert!(
        stderr.contains("sign-flipped"),
        "the help lists the names: {stderr}"
    );
    assert!(
        !Path::new(&dir.0.join("out")).exists(),
        "nothing is written"
    );
}

/// An answer gets its marks for the value its lines give the quantity, in the givens: a
/// restatement (`SumM_x = SumM_x`, `SumM_x = M_x`: M_x is another spelling of ΣM_x), a
/// circular pair, or a value left in another quantity (`SumM_x = Hdot_x`) gives nothing; a
/// relation that holds but takes an earlier wrong value (`T = ½(I_x ω₁² + I_y ω₂²)` after
/// I_x = ¼ m r², I_y = m L² + ½ m r², both wrong) carries the slip.
#[test]
fn marks_follow_the_value_the_lines_give() {
    let dir = OutputDir::new("values");
    let scenes = format!("{}/examples/scenes", env!("CARGO_MANIFEST_DIR"));
    let scheme = dir.write(
        "scheme.toml",
        format!(
            "carried_forward = 0.5\n\
             [[question]]\nid = \"E\"\ncontext = \"principal\"\ngives = \"SumM_x\"\nmarks = 2\n\
             [[question]]\nid = \"R\"\nscene = \"{scenes}/sp18_4_shaft_reactions.scene\"\ngives = [\"C_y\", \"D_y\"]\nmay_use = [\"alpha\"]\nmarks = 2\n\
             [[question]]\nid = \"T\"\nscene = \"{scenes}/sp18_2_rolling_disk.scene\"\ngives = \"T\"\nmarks = 2\n"
        ),
    );
    // E: ΣM_x = I_x ω̇_x − (I_y − I_z) ω_y ω_z; R: C_y = −9M/(16c) − ¼ m c ω²,
    // D_y = −3M/(16c) − ¼ m c ω²; T: ⅛ m r² (6 + r²/L²) ω₁², and with the wrong moments
    // ½(¼ m r² ω₁² + (m L² + ½ m r²) r² ω₁²/L²) ≠ T, right from lines 1 and 2 (1 of 2).
    let csv = "student,question,answer\n\
        ann,E,SumM_x = SumM_x\n\
        ann,R,\"C_y = -D_y - 1/2 m c alpha - 1/2 m c w^2\nD_y = -C_y - 1/2 m c alpha - 1/2 m c w^2\"\n\
        ann,T,T = T\n\
        bob,E,SumM_x = M_x\n\
        bob,R,\"D_y = -3 M/(16 c) - 1/4 m c w^2\nC_y = -D_y - 1/2 m c alpha - 1/2 m c w^2\"\n\
        bob,T,\"I_x = 1/4 m r^2\nI_y = m L^2 + 1/2 m r^2\nw2 = r w1/L\nT = 1/2 (I_x w1^2 + I_y w2^2)\"\n\
        cat,E,M_x = I_x wdot_x - (I_y - I_z) w_y w_z\n\
        dan,E,SumM_x = Hdot_x\n";
    let submissions = dir.write("submissions.csv", csv);
    let out = dir.0.join("out");
    let (code, stdout, stderr) = mark(&scheme, &submissions, &out);
    assert_eq!(code, 0, "{stdout}\n{stderr}");
    // bob's R: D_y right (1), C_y = −D_y − ½ m c (α + ω²) right once line 1's D_y is put in,
    // left in α, which R's may_use allows (1); cat's M_x is ΣM_x (2).
    assert_eq!(
        std::fs::read_to_string(out.join("grades.csv")).expect("grades"),
        "student,E,R,T,total\nann,0,0,0,0\nbob,0,2,1,3\ncat,2,0,0,2\ndan,0,0,0,0\n"
    );
    let dan = std::fs::read_to_string(out.join("feedback/dan.md")).expect("dan");
    assert!(
        dan.contains(r"left in Hdot\_x: give it in the givens"),
        "{dan}"
    );
}

/// A form's export: CRLF line ends (the lines named are the file's), and a quoted answer
/// whose quote is never closed: that row is named, and the rows after it are still marked.
#[test]
fn crlf_lines_and_an_unclosed_quote_are_named_where_they_are() {
    let dir = OutputDir::new("export");
    let scheme = dir.write(
        "scheme.toml",
        "[[question]]\nid = \"E\"\ncontext = \"principal\"\ngives = \"SumM_x\"\nmarks = 2\n",
    );
    let run = |name: &str, csv: &str| {
        let path = dir.write(name, csv);
        let out = dir.0.join(format!("{name}-out"));
        let (code, _, stderr) = mark(&scheme, &path, &out);
        assert_eq!(code, 0, "{stderr}");
        let grades = std::fs::read_to_string(out.join("grades.csv")).expect("grades");
        (path.to_string_lossy().into_owned(), grades, stderr)
    };
    // Line 2-3 ann's quoted answer over two lines, line 4 bob's, line 5 an unknown question.
    let (path, grades, stderr) = run(
        "crlf.csv",
        "student,question,answer\r\nann,E,\"SumM_x = I_x wdot_x - (I_y - I_z) w_y w_z\r\n\"\r\nbob,E,SumM_x = I_x wdot_x\r\nbob,F,x = 1\r\n",
    );
    assert_eq!(grades, "student,E,total\nann,2,2\nbob,0,0\n");
    assert!(stderr.contains(&format!("{path}:5: bob, F: ")), "{stderr}");
    // ann's quote is never closed at line 2; bob (line 3) and cal (line 4) are marked.
    let (path, grades, stderr) = run(
        "unclosed.csv",
        "student,question,answer\nann,E,\"SumM_x = I_x wdot_x\nbob,E,SumM_x = I_x wdot_x - (I_y - I_z) w_y w_z\ncal,E,M_x = I_x wdot_x - (I_y - I_z) w_y w_z\n",
    );
    assert_eq!(grades, "student,E,total\nann,0,0\nbob,2,2\ncal,2,2\n");
    assert!(
        stderr.contains(&format!(
            "{path}:2: ann, E: a quote in the row is never closed"
        )),
        "{stderr}"
    );
}

/// A name the scheme asks for that its context does not derive is refused at its `gives`.
#[test]
fn a_misspelt_quantity_is_refused_at_its_gives() {
    let dir = OutputDir::new("gives");
    let scheme = dir.write(
        "scheme.toml",
        format!(
            "[[question]]\nid = \"Q\"\nscene = \"{}/examples/scenes/sp18_4_shaft_reactions.scene\"\ngives = [\"D_y\", \"D_yy\"]\nmarks = 2\n",
            env!("CARGO_MANIFEST_DIR")
        ),
    );
    let (code, _, stderr) = kinetics(&[
        "mark",
        scheme.to_str().expect("UTF-8"),
        &example("submissions.csv"),
        "-o",
        &dir.0.join("out").to_string_lossy(),
    ]);
    assert_eq!(code, 1);
    assert!(stderr.contains("gives cannot name D_yy"), "{stderr}");
    assert!(stderr.contains(":4:"), "at line 4: {stderr}");
    assert!(stderr.contains("did you mean D_y"), "{stderr}");
}

/// A quantity stated with its name on the right (`1857 N = T_BC`) or times a number
/// (`2 phidot = 5.302 rad/s`), either root of a quantity
/// the scene's equations give two of (a top's slow and fast precession), and a correct answer
/// followed by a line that cannot be read: each earns its marks.
#[test]
fn reversed_statements_either_root_and_an_unread_last_line() {
    let dir = OutputDir::new("roots");
    let scenes = format!("{}/examples/scenes", env!("CARGO_MANIFEST_DIR"));
    let scheme = dir.write(
        "scheme.toml",
        format!(
            "[[question]]\nid = \"T\"\nscene = \"{scenes}/sp18_3_rotating_rod.scene\"\ngives = [\"T_BC\", \"A_x\"]\nmarks = 4\n\
             [[question]]\nid = \"V\"\nscene = \"{scenes}/top_slow_and_fast_precession.scene\"\ngives = \"phidot\"\nmarks = 2\n"
        ),
    );
    // SP 18.3: T_BC = 1857 N, A_x = −843.4 N. The top: φ̇ = 2.651 rad/s or 142.5 rad/s.
    let submissions = dir.write(
        "submissions.csv",
        "student,question,answer\n\
         a,T,\"1857 N = T_BC\n-843.4 N = A_x\"\n\
         b,V,phidot = 142.5 rad/s\n\
         c,V,phidot = 2.651 rad/s\n\
         e,V,2 phidot = 5.302 rad/s\n\
         d,T,\"T_BC = 1857 N\nA_x = -843.4 N\nT_BC = 1857 N (tension)\"\n",
    );
    let out = dir.0.join("out");
    let (code, _, stderr) = mark(&scheme, &submissions, &out);
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(
        std::fs::read_to_string(out.join("grades.csv")).expect("grades"),
        "student,T,V,total\na,4,0,4\nb,0,2,2\nc,0,2,2\ne,0,2,2\nd,4,0,4\n"
    );
    assert!(
        stderr.contains("d, T: line 3 of the answer cannot be read"),
        "{stderr}"
    );
}
