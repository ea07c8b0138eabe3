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
use crate::motion::Friction;
use crate::numeric::verify::Verified;
use crate::oracle::{Oracle, TRAJECTORY_COLUMNS};
use rug::Rational;
use serde_json::{json, Map, Value};
use std::path::{Path, PathBuf};

/// Significant digits of the stored golden data.
pub const GOLDEN_DIGITS: u32 = 30;

/// The format tag of the JSON files.
pub const SCHEMA: &str = "cylroll-golden/1";

/// A curated case.
#[derive(Debug, Clone)]
pub struct Case {
    /// File stem, e.g. `main_roll_roll`.
    pub name: String,
    /// One line of prose.
    pub description: String,
    /// The validated model (with friction: the ideal base, contacts rolling
    /// where a coefficient is given).
    pub model: Model,
    /// Finite Coulomb friction (`mu_floor`, `mu_contact` in the case file),
    /// if any contact has it.
    pub friction: Option<Friction>,
    /// Intervals of the time grid.
    pub steps: u32,
}

/// The parts of a case file's table: its model keys, `description` and
/// `steps` (optional, default 40).
///
/// Errors: an unknown key or a value out of range.
pub fn case_parts(table: &toml::Table) -> Result<(crate::model::input::Pairs, String, u32)> {
    let pairs = pairs_from_toml(table, "case", &crate::model::input::CASE_KEYS)?;
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
    let table = read_toml(path, "case")?;
    let (pairs, description, steps) = case_parts(&table)?;
    let (model, friction) = crate::model::input::model_and_friction(&pairs)?;
    let name = path
        .file_stem()
        .and_then(|s| s.to_str())
        .ok_or_else(|| Error::invalid("case", path.display(), "needs a UTF-8 file name"))?
        .to_string();
    Ok(Case {
        name,
        description,
        model,
        friction,
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

/// A case by name from `golden_dir/cases/NAME.toml`.
pub fn find_case(golden_dir: &Path, name: &str) -> Result<Case> {
    let dir = golden_dir.join("cases");
    let path = dir.join(format!("{name}.toml"));
    if !dir.is_dir() {
        return Err(Error::invalid(
            "case",
            name,
            format!(
                "no case directory {} here (cases are looked for in <golden>/cases; \
                 run from the repository or give --golden DIR)",
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

/// The end of the time grid: t_s rounded *down* to 3 significant digits, so
/// every grid time is an exact decimal before separation.
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

/// Renders a case (deterministic).
pub fn render(case: &Case) -> Result<Rendered> {
    if let Some(fr) = &case.friction {
        return render_friction(case, fr);
    }
    let mut o = Oracle::new(&case.model, GOLDEN_DIGITS)?;
    let sep = o.separation()?;
    let t_s = sep.t_s.clone().ok_or_else(|| {
        Error::not_physical(format!(
            "case {}: infinite times (rest at the top)",
            case.name
        ))
    })?;
    let end = grid_end(&t_s)?;
    let times: Vec<Exact> = (0..=case.steps)
        .map(|i| Exact::rational(&end * Rational::from((i, case.steps))))
        .collect();
    let rows = o.trajectory(&times)?;

    let model = model_map(&case.model);
    let (scalars, bounds) = scalar_maps(
        std::iter::once(&sep.theta_s)
            .chain(sep.t_s.iter())
            .chain(sep.extra.iter()),
    );
    let rows_json: Vec<Value> = rows
        .iter()
        .map(|r| Value::Array(r.iter().map(|v| Value::from(v.text.clone())).collect()))
        .collect();
    let doc = json!({
        "schema": SCHEMA,
        "case": case.name,
        "description": case.description,
        "model": model,
        "digits": GOLDEN_DIGITS.to_string(),
        "provenance": {
            "program": format!("cylroll {}", env!("CARGO_PKG_VERSION")),
            "method": "energy quadrature (tanh-sinh in theta - theta0) for t(theta); Newton inversion for theta(t); \
                       bracketed roots for angles; every value verified at two working precisions",
        },
        "grid": {
            "t_end": rational_text(&end),
            "steps": case.steps.to_string(),
            "note": "t_i = i t_end / steps; t_end is t_s rounded down to 3 significant digits",
        },
        "scalars": scalars,
        "scalar_error_bounds": bounds,
        "notes": sep.notes,
        "columns": TRAJECTORY_COLUMNS,
        "rows": rows_json,
    });
    let json =
        serde_json::to_string_pretty(&doc).map_err(|e| Error::not_physical(e.to_string()))? + "\n";
    let csv = csv_text(
        &TRAJECTORY_COLUMNS,
        rows.iter()
            .map(|r| r.iter().map(|v| v.text.as_str()).collect()),
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
fn csv_text<'a>(columns: &[&str], rows: impl Iterator<Item = Vec<&'a str>>) -> String {
    let mut csv = columns.join(",");
    csv.push('\n');
    for line in rows {
        csv.push_str(&line.join(","));
        csv.push('\n');
    }
    csv
}

/// The format tag of golden files with friction.
pub const SCHEMA_FRICTION: &str = "cylroll-golden-friction/1";

/// Renders a case with friction: the event list, the scalars of the
/// separation and the first impact, and the rows of every phase on a grid
/// from 0 to the impact time rounded down to 3 significant digits.
fn render_friction(case: &Case, fr: &Friction) -> Result<Rendered> {
    let sep = crate::motion::answer::separation(&case.model, fr, GOLDEN_DIGITS)?;
    let t_imp = sep
        .values
        .iter()
        .find(|v| v.name == "t_impact")
        .ok_or_else(|| Error::not_physical("no impact"))?;
    let end = grid_end(t_imp)?;
    let times: Vec<Exact> = (0..=case.steps)
        .map(|i| Exact::rational(&end * Rational::from((i, case.steps))))
        .collect();
    let traj = crate::motion::answer::trajectory(&case.model, fr, GOLDEN_DIGITS, &times)?;
    let mut model = model_map(&case.model);
    model.insert("mu_floor".into(), fr.floor.to_string().into());
    model.insert("mu_contact".into(), fr.contact.to_string().into());
    let (scalars, bounds) = scalar_maps(&sep.values);
    let events: Vec<Value> = sep
        .events
        .iter()
        .map(|e| {
            json!({
                "kind": e.kind.name(),
                "contact": e.which.map(|w| w.name()),
                "mode": e.mode,
                "t": e.t.text,
                "theta": e.theta.text,
            })
        })
        .collect();
    let mut columns: Vec<&str> = crate::motion::columns();
    columns.push("mode");
    let rows_json: Vec<Value> = traj
        .rows
        .iter()
        .zip(&traj.modes)
        .map(|(r, m)| {
            let mut a: Vec<Value> = r.iter().map(|v| Value::from(v.text.clone())).collect();
            a.push(Value::from(m.clone()));
            Value::Array(a)
        })
        .collect();
    let mut notes = sep.notes.clone();
    notes.insert(
        0,
        format!("the first impact is on the {}", sep.impact_surface),
    );
    let doc = json!({
        "schema": SCHEMA_FRICTION,
        "case": case.name,
        "description": case.description,
        "model": model,
        "digits": GOLDEN_DIGITS.to_string(),
        "provenance": {
            "program": format!("cylroll {}", env!("CARGO_PKG_VERSION")),
            "method": "modes of the Coulomb contacts integrated by Chebyshev spectral quadrature in the angle \
                       of the Lagrange-multiplier equations (theta_dot^2 from its linear ODE in theta), events \
                       located as roots on the interpolants and corrected by the exact constraint forces, every \
                       continuation tested for consistency, free flight in closed form; every value verified at \
                       two working precisions with identical event sequences and the energy balance; the same \
                       motion by Gragg-Bulirsch-Stoer extrapolation and Gauss-Legendre collocation agrees \
                       (cylroll verify)",
        },
        "grid": {
            "t_end": rational_text(&end),
            "steps": case.steps.to_string(),
            "note": "t_i = i t_end / steps; t_end is the first impact's time rounded down to 3 significant digits",
        },
        "start_mode": sep.start_mode,
        "events": events,
        "scalars": scalars,
        "scalar_error_bounds": bounds,
        "notes": notes,
        "columns": columns,
        "rows": rows_json,
    });
    let json =
        serde_json::to_string_pretty(&doc).map_err(|e| Error::not_physical(e.to_string()))? + "\n";
    let csv = csv_text(
        &columns,
        traj.rows.iter().zip(&traj.modes).map(|(r, m)| {
            let mut line: Vec<&str> = r.iter().map(|v| v.text.as_str()).collect();
            line.push(m);
            line
        }),
    );
    Ok(Rendered { json, csv })
}

pub use fileset::write_atomic;

/// Renders every case of `golden_dir/cases` into `golden_dir/data`. All cases
/// are computed before anything is written, so a failure writes nothing.
pub fn write_all(golden_dir: &Path) -> Result<String> {
    let cases = load_cases(golden_dir)?;
    let mut out = Vec::new();
    for c in &cases {
        out.push((c.name.clone(), render(c)?));
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
