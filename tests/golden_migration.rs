//! The golden schema's migration (1 → 2) changed no value: every number of
//! every schema-1 file (`tests/fixtures/golden_v1`, the files as they were)
//! is in schema 2 unchanged to its verified digits — every scalar and event
//! in `golden/data`, and every cell of every row recomputed at the schema-1
//! file's own times. Only keys and layout moved, and φ2 of a contact that
//! starts rolling, now counted from 0 at t = 0: the schema-1 φ2 is the
//! paper's, r1 θ0/r2 below.

use cylroll::golden::{find_case, SCHEMAS_V1};
use cylroll::motion::Phase;
use cylroll::oracle::{trajectory, Options};
use rug::Float;
use serde_json::Value;
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn read(p: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(p).unwrap()).unwrap()
}

/// The unit of the last digit of a decimal string.
fn last_unit(s: &str) -> Float {
    let p = 256;
    let t = s.trim_start_matches('-');
    let (mant, exp) = match t.find(['e', 'E']) {
        Some(i) => (&t[..i], t[i + 1..].parse::<i32>().unwrap()),
        None => (t, 0),
    };
    let frac = mant.split_once('.').map_or(0, |(_, f)| f.len() as i32);
    use rug::ops::Pow;
    Float::with_val(p, Float::with_val(p, 10u32).pow(exp - frac))
}

/// A schema-1 mode ("floor stick, contact slip+", "flight") as a tag.
fn v1_mode_tag(s: &str) -> String {
    match s.split_once(", ") {
        Some((f, c)) => format!(
            "{}/{}",
            f.trim_start_matches("floor "),
            c.trim_start_matches("contact ")
        ),
        None => s.to_string(),
    }
}

#[test]
fn every_schema_1_value_is_unchanged_in_schema_2() {
    let dir = root().join("tests/fixtures/golden_v1");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    files.sort();
    assert!(files.len() >= 19, "{} schema-1 files", files.len());
    let mut compared = 0usize;
    for f in &files {
        let old = read(f);
        let name = old["case"].as_str().unwrap();
        assert!(SCHEMAS_V1.contains(&old["schema"].as_str().unwrap()));
        let new = read(&root().join(format!("golden/data/{name}.json")));
        assert_eq!(new["schema"], "cylroll-golden/2");
        // the scalars: the same text under the same key
        for (k, v) in old["scalars"].as_object().unwrap() {
            assert_eq!(&new["scalars"][k], v, "{name}: scalar {k}");
            compared += 1;
        }
        // the events: schema 2 adds the branch point (indeterminate)
        if let Some(evs) = old["events"].as_array() {
            let new_evs: Vec<&Value> = new["events"]
                .as_array()
                .unwrap()
                .iter()
                .filter(|e| e["kind"] != "indeterminate")
                .collect();
            assert_eq!(evs.len(), new_evs.len(), "{name}: events");
            for (a, b) in evs.iter().zip(new_evs) {
                for k in ["kind", "contact", "t", "theta"] {
                    assert_eq!(a[k], b[k], "{name}: event {k}");
                    compared += 1;
                }
                let mode = a["mode"].as_str().map(v1_mode_tag);
                assert_eq!(mode.as_deref(), b["mode"].as_str(), "{name}: event mode");
            }
            assert_eq!(
                old["start_mode"].as_str().map(v1_mode_tag),
                new["start_mode"].as_str().map(String::from)
            );
        }
        // the rows, recomputed at the schema-1 times
        let case = find_case(&root().join("golden"), name).unwrap();
        let cols: Vec<&str> = old["columns"]
            .as_array()
            .unwrap()
            .iter()
            .map(|c| c.as_str().unwrap())
            .collect();
        let rows = old["rows"].as_array().unwrap();
        let times: Vec<cylroll::exact::Exact> = rows
            .iter()
            .map(|r| cylroll::exact::Exact::parse("t", r[0].as_str().unwrap(), false).unwrap())
            .collect();
        let digits: u32 = old["digits"].as_str().unwrap().parse().unwrap();
        let ans = trajectory(&case.model, &times, &Options::digits(digits)).unwrap();
        let m = &case.model;
        let shift = if *m.contact() != cylroll::model::Law::Frictionless {
            let p = m.params();
            Float::with_val(256, &p.r1) * m.start().theta0.to_float(256)
                / Float::with_val(256, &p.r2)
        } else {
            Float::new(256)
        };
        for (r, row) in rows.iter().zip(&ans.rows) {
            for (c, v) in cols.iter().zip(r.as_array().unwrap()) {
                let v = v.as_str().unwrap();
                if *c == "mode" {
                    assert_eq!(Phase::parse(v).map(|p| p.tag()), Some(row.phase.tag()));
                    continue;
                }
                let i = cylroll::motion::point::column_index(c).unwrap();
                let now = &row.values[i];
                if *c == "phi2" {
                    // the gauge: φ2 (schema 2) = φ2 (schema 1) + r1 θ0/r2, each
                    // rounded to its own digits
                    let a = Float::with_val(256, Float::parse(v).unwrap());
                    let b = Float::with_val(256, Float::parse(&now.text).unwrap());
                    let d = Float::with_val(256, &b - &a) - &shift;
                    let room = (last_unit(v) + last_unit(&now.text)) / 2u32;
                    assert!(
                        d.abs() <= room,
                        "{name} t = {}: phi2 {v} -> {}",
                        r[0],
                        now.text
                    );
                } else {
                    assert_eq!(now.text, v, "{name} t = {}: {c}", r[0]);
                }
                compared += 1;
            }
        }
    }
    assert!(compared > 10_000, "{compared} values compared");
}
