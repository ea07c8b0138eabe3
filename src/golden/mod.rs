//! Golden data: curated cases (`golden/cases/*.toml`) rendered to JSON and CSV
//! with verified digits only, and the judge that holds another program's CSV
//! against the oracle (`check`).
//!
//! Everything rendered is deterministic text: decimal strings, a stable key
//! order, no timestamps or paths. Files are written atomically.

pub mod fileset;

use crate::error::{Error, Result};
use crate::exact::{rational_text, Exact};
use crate::model::input::{pairs_from_toml, read_toml};
use crate::model::Model;
use crate::numeric::verify::Verified;
use crate::oracle::{self, Answer, Options};
use rug::Rational;
use serde_json::{json, Map, Value};
use std::path::{Path, PathBuf};

/// Significant digits of the stored golden data.
pub const GOLDEN_DIGITS: u32 = 30;

/// The format tag of the JSON files: one schema for every contact law.
pub const SCHEMA: &str = "cylroll-golden/2";

/// The format tags of the first schema (read by `check` and the migration
/// test): the ideal models' files and those with friction. In both, φ2 of a
/// rolling contact is the paper's (r2 φ2 = r1(φ1 − θ)), r1 θ0/r2 below
/// today's φ2.
pub const SCHEMAS_V1: [&str; 2] = ["cylroll-golden/1", "cylroll-golden-friction/1"];

/// A curated case.
#[derive(Debug, Clone)]
pub struct Case {
    /// File stem, e.g. `main_roll_roll`.
    pub name: String,
    /// One line of prose.
    pub description: String,
    /// The validated model.
    pub model: Model,
    /// Intervals of the time grid.
    pub steps: u32,
}

/// The parts of a case file's table: its model keys, `description` and
/// `steps` (optional, default 40); `what` names the file's role in
/// messages (`case`, or `params` for `check --params`).
///
/// Errors: an unknown key or a value out of range.
pub fn case_parts(
    table: &toml::Table,
    what: &str,
) -> Result<(crate::model::input::Pairs, String, u32)> {
    let pairs = pairs_from_toml(table, what, &crate::model::input::CASE_KEYS)?;
    let description = match table.get("description") {
        Some(toml::Value::String(s)) => s.clone(),
        _ => String::new(),
    };
    let steps = match table.get("steps") {
        None => 40,
        Some(toml::Value::Integer(n)) if (1..=10_000).contains(n) => *n as u32,
        Some(v) => {
            return Err(Error::invalid(
                "steps",
                v,
                "must be an integer between 1 and 10000",
            ))
        }
    };
    Ok((pairs, description, steps))
}

/// Reads one case file: `description`, `steps` (optional, default 40) and the
/// model keys of `--params`.
pub fn load_case(path: &Path) -> Result<Case> {
    let name = path
        .file_stem()
        .and_then(|s| s.to_str())
        .ok_or_else(|| Error::invalid("case", path.display(), "needs a UTF-8 file name"))?
        .to_string();
    read_case(path, "case", name)
}

/// A case from the TOML file `path` (read as `what`, `case` or `params`, for
/// messages) named `name`; a bad value's error names the file, as `--params`
/// does (`m1 (in cases/x.toml)`).
pub fn read_case(path: &Path, what: &str, name: String) -> Result<Case> {
    use crate::model::input::in_file;
    let table = read_toml(path, what)?;
    let (pairs, description, steps) = case_parts(&table, what).map_err(|e| in_file(e, path))?;
    // a value's error names the file in its name (m1 (in FILE)); any other
    // (a start inside a body, …) is led by the file
    let model = crate::model::input::model_from_pairs(&pairs).map_err(|e| match e {
        Error::InvalidParameter { .. } => in_file(e, path),
        other => other.context(&path.display().to_string()),
    })?;
    Ok(Case {
        name,
        description,
        model,
        steps,
    })
}

/// The case files `dir/cases/*.toml`, sorted.
fn case_paths(golden_dir: &Path) -> Result<Vec<PathBuf>> {
    let dir = golden_dir.join("cases");
    let mut paths: Vec<PathBuf> = std::fs::read_dir(&dir)
        .map_err(|e| Error::Io {
            path: dir.display().to_string(),
            what: e.to_string(),
        })?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    paths.sort();
    Ok(paths)
}

/// All cases of `dir/cases`, sorted by name.
pub fn load_cases(golden_dir: &Path) -> Result<Vec<Case>> {
    case_paths(golden_dir)?
        .iter()
        .map(|p| load_case(p))
        .collect()
}

/// The names (file stems) of the cases in `golden_dir/cases`, sorted.
pub fn case_names(golden_dir: &Path) -> Result<Vec<String>> {
    Ok(case_paths(golden_dir)?
        .iter()
        .filter_map(|p| p.file_stem().and_then(|s| s.to_str()).map(String::from))
        .collect())
}

/// The curated cases built into the program, (name, TOML text) sorted by
/// name: `golden/cases/*.toml` at build time, so that `check --case NAME`
/// works from any directory (the reference itself is computed, never read
/// from `golden/data`).
pub const BUILTIN: &[(&str, &str)] = &[
    ("bobbin", include_str!("../../golden/cases/bobbin.toml")),
    (
        "fixed_roll",
        include_str!("../../golden/cases/fixed_roll.toml"),
    ),
    (
        "fixed_slip",
        include_str!("../../golden/cases/fixed_slip.toml"),
    ),
    (
        "heavy_upper_restick",
        include_str!("../../golden/cases/heavy_upper_restick.toml"),
    ),
    (
        "hollow_upper",
        include_str!("../../golden/cases/hollow_upper.toml"),
    ),
    (
        "main_floor_slips",
        include_str!("../../golden/cases/main_floor_slips.toml"),
    ),
    (
        "main_mu_0_3",
        include_str!("../../golden/cases/main_mu_0_3.toml"),
    ),
    (
        "main_mu_1",
        include_str!("../../golden/cases/main_mu_1.toml"),
    ),
    (
        "main_mu_10",
        include_str!("../../golden/cases/main_mu_10.toml"),
    ),
    (
        "main_roll_roll",
        include_str!("../../golden/cases/main_roll_roll.toml"),
    ),
    (
        "main_static_kinetic",
        include_str!("../../golden/cases/main_static_kinetic.toml"),
    ),
    (
        "moving_start",
        include_str!("../../golden/cases/moving_start.toml"),
    ),
    (
        "mujoco_main",
        include_str!("../../golden/cases/mujoco_main.toml"),
    ),
    (
        "roll_slip",
        include_str!("../../golden/cases/roll_slip.toml"),
    ),
    ("si_units", include_str!("../../golden/cases/si_units.toml")),
    (
        "slip_roll",
        include_str!("../../golden/cases/slip_roll.toml"),
    ),
    (
        "slip_slip",
        include_str!("../../golden/cases/slip_slip.toml"),
    ),
    ("unequal", include_str!("../../golden/cases/unequal.toml")),
    (
        "unequal_friction",
        include_str!("../../golden/cases/unequal_friction.toml"),
    ),
];

/// The model keys, description and grid size of a case file's text (`name`
/// for messages).
///
/// Errors: text that is not TOML; as [`case_parts`].
pub fn case_text_parts(
    name: &str,
    text: &str,
) -> Result<(crate::model::input::Pairs, String, u32)> {
    let table: toml::Table = text.parse().map_err(|e: toml::de::Error| {
        Error::invalid("case", name, crate::model::input::toml_refusal(text, &e))
    })?;
    case_parts(&table, "case")
}

/// A built-in case by name ([`BUILTIN`]).
///
/// Errors: an unknown name (the known ones listed); a case file that does
/// not read (a build of a broken checkout).
pub fn builtin_case(name: &str) -> Result<Case> {
    let Some((stem, text)) = BUILTIN.iter().find(|(n, _)| *n == name) else {
        let known: Vec<&str> = BUILTIN.iter().map(|(n, _)| *n).collect();
        return Err(Error::invalid(
            "case",
            name,
            format!(
                "unknown case; the built-in cases: {} (or give --params FILE, or --golden DIR \
                 for DIR/cases/NAME.toml)",
                known.join(", ")
            ),
        ));
    };
    let (pairs, description, steps) = case_text_parts(name, text)?;
    let model = crate::model::input::model_from_pairs(&pairs)
        .map_err(|e| Error::invalid("case", name, format!("has a bad value: {e}")))?;
    Ok(Case {
        name: stem.to_string(),
        description,
        model,
        steps,
    })
}

/// A case by name from `golden_dir/cases/NAME.toml`.
pub fn find_case(golden_dir: &Path, name: &str) -> Result<Case> {
    let dir = golden_dir.join("cases");
    let path = dir.join(format!("{name}.toml"));
    if !dir.is_dir() {
        return Err(Error::invalid(
            "case",
            name,
            format!(
                "no case directory {} (--golden DIR reads DIR/cases/NAME.toml; without \
                 --golden the built-in cases are used)",
                dir.display()
            ),
        ));
    }
    if !path.exists() {
        let known: Vec<String> = case_names(golden_dir).unwrap_or_default();
        return Err(Error::invalid(
            "case",
            name,
            format!(
                "unknown case in {}; known: {}",
                dir.display(),
                if known.is_empty() {
                    "none".to_string()
                } else {
                    known.join(", ")
                }
            ),
        ));
    }
    load_case(&path)
}

/// The rendered golden data of one case.
#[derive(Debug, Clone)]
pub struct Rendered {
    /// `golden/data/<case>.json`.
    pub json: String,
    /// `golden/data/<case>.csv`.
    pub csv: String,
}

/// The end of the time grid: a time rounded *down* to 3 significant
/// digits, so that every grid time is an exact decimal before it.
fn grid_end(t_s: &Verified) -> Result<Rational> {
    let e = Exact::parse("t_s", &t_s.text, false)?;
    if e.signum() <= 0 {
        return Err(Error::not_physical("the separation time is not positive"));
    }
    // scale = 10^(exponent − 2) so that floor(t/scale)·scale keeps 3 digits
    let mag = e.to_f64().log10().floor() as i32;
    let scale = if mag - 2 >= 0 {
        Rational::from(rug::Integer::from(rug::Integer::u_pow_u(
            10,
            (mag - 2) as u32,
        )))
    } else {
        Rational::from((
            1,
            rug::Integer::from(rug::Integer::u_pow_u(10, (2 - mag) as u32)),
        ))
    };
    let n = Rational::from(&e.coef / &scale).floor();
    Ok(n * scale)
}

/// The time at which the motion ends (the first impact, a lift-off).
fn end_time(sep: &Answer) -> Result<&Verified> {
    sep.value("t_impact")
        .or_else(|| sep.events.last().map(|e| &e.t))
        .ok_or_else(|| {
            Error::not_physical(
                "the motion has no end in time to lay a grid of times on (from rest exactly at \
                 the unstable top, theta0 = 0 and thetadot0 = 0, every time is infinite); give \
                 a small theta0 or thetadot0",
            )
        })
}

/// The method of each route, for the provenance.
fn provenance(sep: &Answer) -> String {
    use crate::motion::Route;
    let mut parts = Vec::new();
    if sep.routes.contains(&Route::Energy) {
        parts.push(
            "the conservative first phase by the energy route (theta_dot^2 in closed form, t(theta) by \
             quadrature, theta(t) by Taylor series or Chebyshev inversion, events as roots of \
             polynomials in cos theta; a row's other columns from its verified delta at the higher \
             precision, with the error delta's bound and the roundings carry into them)",
        );
    }
    if sep.routes.contains(&Route::Spectral) || sep.routes.contains(&Route::Gbs) {
        parts.push(
            "dissipative phases by Chebyshev spectral quadrature in the angle of the \
             Lagrange-multiplier equations (theta_dot^2 from its linear ODE in theta), events \
             located on the interpolants and corrected by the exact constraint forces, every \
             continuation tested for consistency (cross-checked by Gragg-Bulirsch-Stoer \
             extrapolation and Gauss-Legendre collocation: cylroll verify)",
        );
    }
    parts.push("the free flight in closed form");
    parts.push(
        "every value verified at two working precisions with identical event sequences and the \
         energy balance",
    );
    parts.join("; ")
}

/// Renders a case (deterministic): the motion to its end (events, scalars,
/// notes) and the rows of every phase on a grid from 0 to the end of the
/// motion (the first impact) rounded down to 3 significant digits.
pub fn render(case: &Case) -> Result<Rendered> {
    let opts = Options::digits(GOLDEN_DIGITS);
    let sep = oracle::separation(&case.model, &opts)?;
    let end = grid_end(end_time(&sep)?)?;
    let times: Vec<Exact> = (0..=case.steps)
        .map(|i| Exact::rational(&end * Rational::from((i, case.steps))))
        .collect();
    let traj = oracle::trajectory(&case.model, &times, &opts)?;
    let (scalars, bounds) = scalar_maps(&sep.values);
    let events: Vec<Value> = sep
        .events
        .iter()
        .map(|e| {
            json!({
                "kind": e.kind.name(),
                "contact": e.which.map(|w| w.name()),
                "mode": e.phase.map(|p| p.tag()),
                "t": e.t.text,
                "theta": e.theta.text,
            })
        })
        .collect();
    let mut columns: Vec<&str> = crate::motion::COLUMNS.to_vec();
    columns.push("mode");
    let rows_json: Vec<Value> = traj
        .rows
        .iter()
        .map(|r| {
            let mut a: Vec<Value> = r
                .values
                .iter()
                .map(|v| Value::from(v.text.clone()))
                .collect();
            a.push(Value::from(r.phase.tag()));
            Value::Array(a)
        })
        .collect();
    let doc = json!({
        "schema": SCHEMA,
        "case": case.name,
        "description": case.description,
        "model": model_map(&case.model),
        "branch": sep.branch.name(),
        "digits": GOLDEN_DIGITS.to_string(),
        "provenance": {
            "program": format!("cylroll {}", env!("CARGO_PKG_VERSION")),
            "method": provenance(&sep),
        },
        "grid": {
            "t_end": rational_text(&end),
            "steps": case.steps.to_string(),
            "note": "t_i = i t_end / steps; t_end is the end of the motion (the first impact) rounded down to 3 significant digits",
        },
        "start_mode": sep.start_mode.map(|m| m.tag()),
        "end": sep.end.map(|e| e.name()),
        "events": events,
        "scalars": scalars,
        "scalar_error_bounds": bounds,
        "notes": sep.notes,
        "columns": columns,
        "rows": rows_json,
    });
    let json =
        serde_json::to_string_pretty(&doc).map_err(|e| Error::not_physical(e.to_string()))? + "\n";
    let csv = csv_text(
        &columns,
        traj.rows.iter().map(|r| {
            let mut line: Vec<String> = r.values.iter().map(|v| v.text.clone()).collect();
            line.push(r.phase.tag());
            line
        }),
    );
    Ok(Rendered { json, csv })
}

/// The model's keys and exact values, in the echo order.
fn model_map(model: &Model) -> Map<String, Value> {
    let mut m = Map::new();
    for (k, v) in model.echo() {
        m.insert(k.into(), v.into());
    }
    m
}

/// The `scalars` and `scalar_error_bounds` objects of verified values.
fn scalar_maps<'a>(
    values: impl IntoIterator<Item = &'a Verified>,
) -> (Map<String, Value>, Map<String, Value>) {
    let mut scalars = Map::new();
    let mut bounds = Map::new();
    for v in values {
        scalars.insert(v.name.clone(), v.text.clone().into());
        bounds.insert(v.name.clone(), v.err_text().into());
    }
    (scalars, bounds)
}

/// A CSV with a header row.
fn csv_text(columns: &[&str], rows: impl Iterator<Item = Vec<String>>) -> String {
    let mut csv = columns.join(",");
    csv.push('\n');
    for line in rows {
        csv.push_str(&line.join(","));
        csv.push('\n');
    }
    csv
}

pub use fileset::write_atomic;

/// Renders every case of `golden_dir/cases` into `golden_dir/data`. All cases
/// are computed before anything is written, so a failure writes nothing.
pub fn write_all(golden_dir: &Path) -> Result<String> {
    let cases = load_cases(golden_dir)?;
    if cases.is_empty() {
        return Err(Error::invalid(
            "--dir",
            golden_dir.display(),
            format!(
                "has no case files: golden reads DIR/cases/*.toml ({} holds none)",
                golden_dir.join("cases").display()
            ),
        ));
    }
    // an unwritable destination is refused before the work
    fileset::check_writable(golden_dir, &["data"])?;
    let mut out = Vec::new();
    for c in &cases {
        let file = golden_dir.join("cases").join(format!("{}.toml", c.name));
        out.push((
            c.name.clone(),
            render(c).map_err(|e| e.context(&format!("case {} ({})", c.name, file.display())))?,
        ));
    }
    let data = golden_dir.join("data");
    let mut summary = String::new();
    let mut files = Vec::new();
    for (name, r) in out {
        summary.push_str(&format!("{name}: data/{name}.json, data/{name}.csv\n"));
        files.push((PathBuf::from(format!("{name}.json")), r.json.into_bytes()));
        files.push((PathBuf::from(format!("{name}.csv")), r.csv.into_bytes()));
    }
    // the data change as one set (see fileset): never a new json beside an old csv
    fileset::write_set(&data, &files)?;
    Ok(summary)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn builtin_cases_are_the_case_files() {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("golden");
        let names = case_names(&dir).unwrap();
        let builtin: Vec<&str> = BUILTIN.iter().map(|(n, _)| *n).collect();
        assert_eq!(names, builtin, "golden/cases and golden::BUILTIN differ");
        for name in &names {
            let text = std::fs::read_to_string(dir.join("cases").join(format!("{name}.toml")));
            let built = BUILTIN.iter().find(|(n, _)| n == name).unwrap().1;
            assert_eq!(text.unwrap(), built, "{name}");
            let a = builtin_case(name).unwrap();
            let b = find_case(&dir, name).unwrap();
            assert_eq!(
                (a.model, a.steps, a.description),
                (b.model, b.steps, b.description)
            );
        }
        let e = builtin_case("no_such_case").unwrap_err().to_string();
        assert!(
            e.contains("no_such_case") && e.contains("main_mu_0_3"),
            "{e}"
        );
    }
}
