//! The corpus of `kinetics check` (`tests/data/check_corpus.txt`): claims as people type
//! them, each with the verdict and the reading derived by hand. Each context's claims go
//! to the binary as one claims file (one run per context, `--format json`), and every
//! claim's verdict and reading must be the corpus's; all mismatches are reported together.

use crate::common::check::{check_file, try_judged, ClaimsFile};
use kinetics::check::reading_names;
use std::collections::BTreeMap;

/// One line of the corpus: `CONTEXT | VERDICT | READING | CLAIM`.
struct Entry {
    /// The line in the corpus file, 1-based.
    line: usize,
    context: String,
    verdict: String,
    /// `None` for `-`.
    reading: Option<String>,
    claim: String,
}

const VERDICTS: [&str; 4] = ["holds", "differs", "undecided", "error"];

fn corpus() -> Vec<Entry> {
    let text = include_str!("../data/check_corpus.txt");
    text.lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty() && !l.trim_start().starts_with('#'))
        .map(|(i, l)| {
            let fields: Vec<&str> = l.splitn(4, '|').map(str::trim).collect();
            let [context, verdict, reading, claim] = fields[..] else {
                panic!(
                    "corpus line {}: not CONTEXT | VERDICT | READING | CLAIM",
                    i + 1
                );
            };
            assert!(
                VERDICTS.contains(&verdict),
                "corpus line {}: verdict {verdict}",
                i + 1
            );
            assert!(
                reading == "-" || reading_names().contains(&reading),
                "corpus line {}: no reading is named {reading}",
                i + 1
            );
            Entry {
                line: i + 1,
                context: context.to_owned(),
                verdict: verdict.to_owned(),
                reading: (reading != "-").then(|| reading.to_owned()),
                claim: claim.to_owned(),
            }
        })
        .collect()
}

#[test]
fn the_corpus_is_large_and_covers_every_reading() {
    let corpus = corpus();
    assert!(corpus.len() >= 500, "{} claims", corpus.len());
    let true_claims = corpus.iter().filter(|e| e.verdict == "holds").count();
    assert!(true_claims >= 300, "{true_claims} true claims");
    let named = corpus.iter().filter(|e| e.reading.is_some()).count();
    assert!(named >= 240, "{named} claims with a named slip");
    assert!(corpus
        .iter()
        .all(|e| e.verdict != "holds" || e.reading.is_none()));
    // Every slip of the mechanics planted a dozen times and more, over several contexts;
    // every other reading at least a few times.
    let slips = kinetics::mechanics::slip::Slip::ALL.map(|s| s.name());
    for name in reading_names() {
        let claims: Vec<&Entry> = corpus
            .iter()
            .filter(|e| e.reading.as_deref() == Some(name))
            .collect();
        let least = if slips.contains(&name) { 12 } else { 3 };
        assert!(
            claims.len() >= least,
            "{} claims read as {name}",
            claims.len()
        );
    }
}

#[test]
fn every_claim_of_the_corpus_gets_its_verdict_and_reading() {
    let mut groups: BTreeMap<&str, Vec<&Entry>> = BTreeMap::new();
    let corpus = corpus();
    for e in &corpus {
        groups.entry(&e.context).or_default().push(e);
    }
    let mut mismatches = Vec::new();
    for (n, (context, entries)) in groups.iter().enumerate() {
        let text: String = entries.iter().map(|e| format!("{}\n", e.claim)).collect();
        let file = ClaimsFile::new(&format!("corpus-{n}"), &text);
        let run = check_file(context, &file);
        let expected_code = if entries.iter().any(|e| e.verdict == "differs") {
            1
        } else {
            0
        };
        if run.code != expected_code {
            mismatches.push(format!(
                "{context}: exit {} where {expected_code} was expected; stderr: {}",
                run.code, run.stderr
            ));
        }
        let claims = match try_judged(&run) {
            Ok((claims, _)) => claims,
            Err(e) => {
                mismatches.push(format!("{context}: {e}"));
                continue;
            }
        };
        for (position, e) in entries.iter().enumerate() {
            // The claims file has one claim a line, in the corpus's order.
            let line = position as u64 + 1;
            let expected = (e.verdict.as_str(), e.reading.as_deref());
            let got = claims
                .iter()
                .find(|c| c.line == line)
                .map(|c| (c.verdict.as_str(), c.reading.as_deref()));
            if got != Some(expected) {
                mismatches.push(format!(
                    "corpus line {} ({context}): {}\n    expected {expected:?}, got {got:?}",
                    e.line, e.claim
                ));
            }
        }
    }
    assert!(
        mismatches.is_empty(),
        "{} mismatches with the hand derivations ({} claims in {} contexts):\n{}",
        mismatches.len(),
        corpus.len(),
        groups.len(),
        mismatches.join("\n")
    );
}
