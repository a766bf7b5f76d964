//! Issue 18, item 6: `docs/solution.schema.json` describes `kinetics solve --format json`
//! (and its `--numbers` page). Every example's output validates; a document with a field
//! missing, a string where a number belongs, a vector of two components or a field the
//! schema does not name is rejected.
//!
//! The validator here is the subset of JSON Schema 2020-12 the file uses (`$ref` into
//! `$defs`, `type`, `required`, `properties`, `additionalProperties: false`, `items`,
//! `minItems`, `maxItems`, `oneOf`); any other keyword is refused, so the schema cannot
//! grow past what is checked. (Python's `jsonschema` agrees on the examples.)

use super::common::binary::kinetics;
use super::common::examples::example_scenes;
use serde_json::{json, Value};

fn schema() -> Value {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/docs/solution.schema.json");
    serde_json::from_str(&std::fs::read_to_string(path).expect("the schema exists"))
        .expect("the schema is JSON")
}

/// The places where `doc` breaks `schema` (`root` holds the `$defs`); empty when it is valid.
fn violations(root: &Value, schema: &Value, doc: &Value, at: &str) -> Vec<String> {
    let mut out = Vec::new();
    let rules = schema.as_object().expect("a schema is an object");
    for (keyword, rule) in rules {
        match keyword.as_str() {
            "$schema" | "$defs" | "title" | "description" => {}
            "$ref" => {
                let name = rule.as_str().and_then(|r| r.strip_prefix("#/$defs/"));
                let target = &root["$defs"][name.expect("a $ref into $defs")];
                assert!(!target.is_null(), "{rule} names no definition");
                out.extend(violations(root, target, doc, at));
            }
            "type" => {
                let types: Vec<&str> = match rule {
                    Value::String(t) => vec![t],
                    Value::Array(ts) => ts.iter().filter_map(Value::as_str).collect(),
                    _ => panic!("type {rule}"),
                };
                if !types.iter().any(|t| is_type(doc, t)) {
                    out.push(format!("{at}: {doc} is not of type {rule}"));
                }
            }
            "required" => {
                for field in rule.as_array().expect("required is a list") {
                    let field = field.as_str().expect("a field name");
                    if doc.is_object() && doc.get(field).is_none() {
                        out.push(format!("{at}: '{field}' is missing"));
                    }
                }
            }
            "properties" => {
                for (field, sub) in rule.as_object().expect("properties") {
                    if let Some(v) = doc.get(field) {
                        out.extend(violations(root, sub, v, &format!("{at}/{field}")));
                    }
                }
            }
            "additionalProperties" => {
                assert_eq!(rule, &json!(false), "only additionalProperties: false");
                let named = &schema["properties"];
                for field in doc.as_object().into_iter().flat_map(|o| o.keys()) {
                    if named.get(field).is_none() {
                        out.push(format!("{at}: '{field}' is not in the schema"));
                    }
                }
            }
            "items" => {
                for (k, item) in doc.as_array().into_iter().flatten().enumerate() {
                    out.extend(violations(root, rule, item, &format!("{at}/{k}")));
                }
            }
            "minItems" | "maxItems" => {
                let bound = rule.as_u64().expect("a count") as usize;
                if let Some(n) = doc.as_array().map(Vec::len) {
                    if (keyword == "minItems" && n < bound) || (keyword == "maxItems" && n > bound)
                    {
                        out.push(format!("{at}: {n} items, {keyword} {bound}"));
                    }
                }
            }
            "oneOf" => {
                let branches: Vec<Vec<String>> = rule
                    .as_array()
                    .expect("oneOf is a list")
                    .iter()
                    .map(|s| violations(root, s, doc, at))
                    .collect();
                let valid = branches.iter().filter(|v| v.is_empty()).count();
                if valid != 1 {
                    out.push(format!("{at}: {valid} of oneOf match"));
                    // Why none matched: each branch's own violations.
                    out.extend(branches.into_iter().flatten());
                }
            }
            other => panic!("the validator does not know the keyword {other}"),
        }
    }
    out
}

fn is_type(doc: &Value, t: &str) -> bool {
    match t {
        "object" => doc.is_object(),
        "array" => doc.is_array(),
        "string" => doc.is_string(),
        "number" => doc.is_number(),
        "integer" => doc.is_i64() || doc.is_u64(),
        "boolean" => doc.is_boolean(),
        "null" => doc.is_null(),
        _ => panic!("unknown type {t}"),
    }
}

fn check(doc: &Value) -> Vec<String> {
    let root = schema();
    violations(&root, &root, doc, "")
}

fn solve_json(scene: &std::path::Path, numbers: bool) -> Value {
    let path = scene.to_string_lossy();
    let mut args = vec!["solve", &path, "--format", "json"];
    if numbers {
        args.push("--numbers");
    }
    let (code, out, err) = kinetics(&args);
    assert_eq!(code, 0, "{path}: {err}");
    serde_json::from_str(&out).expect("the output is JSON")
}

#[test]
fn every_examples_json_validates() {
    for scene in example_scenes() {
        for numbers in [false, true] {
            let errors = check(&solve_json(&scene, numbers));
            assert!(
                errors.is_empty(),
                "{} (--numbers: {numbers}): {errors:?}",
                scene.display()
            );
        }
    }
}

#[test]
fn wrong_documents_are_rejected() {
    let scene = std::path::PathBuf::from(super::common::binary::scene("sp18_3_rotating_rod"));
    let good = solve_json(&scene, false);
    let wrong = |edit: &dyn Fn(&mut Value)| {
        let mut doc = good.clone();
        edit(&mut doc);
        check(&doc)
    };
    let missing = wrong(&|d| {
        d["results"][0].as_object_mut().unwrap().remove("unit");
    });
    assert!(
        missing.iter().any(|e| e.contains("'unit' is missing")),
        "{missing:?}"
    );
    let string = wrong(&|d| d["results"][2]["value"] = json!("1857"));
    assert!(!string.is_empty(), "a string accepted as a value");
    let short = wrong(&|d| d["results"][0]["value"] = json!([1.0, 2.0]));
    assert!(!short.is_empty(), "a vector of two components accepted");
    let extra = wrong(&|d| d["givens"][0]["note"] = json!("x"));
    assert!(
        extra
            .iter()
            .any(|e| e.contains("'note' is not in the schema")),
        "{extra:?}"
    );
    let si = wrong(&|d| d["givens"][0]["si_value"] = json!("2.4"));
    assert!(!si.is_empty(), "a string accepted as si_value");
    let numbers = solve_json(&scene, true);
    let mut no_intermediate = numbers.clone();
    no_intermediate
        .as_object_mut()
        .unwrap()
        .remove("intermediate");
    assert!(!check(&no_intermediate).is_empty());
    let mut named = numbers;
    named["intermediate"][0]["values"][0]["value"] = json!(null);
    assert!(
        !check(&named).is_empty(),
        "an intermediate value without a number"
    );
}

#[test]
fn the_validator_checks_what_it_reads() {
    let root = json!({"$defs": {"v": {"type": "array", "items": {"type": "number"}, "minItems": 3}},
        "type": "object", "required": ["a"], "additionalProperties": false,
        "properties": {"a": {"oneOf": [{"$ref": "#/$defs/v"}, {"type": "null"}]}}});
    let v = |doc: Value| violations(&root, &root, &doc, "");
    assert!(v(json!({"a": [1, 2, 3]})).is_empty());
    assert!(v(json!({"a": null})).is_empty());
    assert!(!v(json!({"a": [1, 2]})).is_empty());
    assert!(!v(json!({"a": [1, "2", 3]})).is_empty());
    assert!(!v(json!({})).is_empty());
    assert!(!v(json!({"a": null, "b": 1})).is_empty());
    assert!(!v(json!([])).is_empty());
}
