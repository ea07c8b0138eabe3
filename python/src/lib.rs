//! `cylroll._cylroll`: the native half of the Python package `cylroll`.
//!
//! Thin on purpose: every function takes the model as key/value pairs of exact
//! decimal text (the keys of `--params`, built by the Python class
//! `cylroll.Model`), calls the library, and returns plain Python data — the
//! verified values as `(name, text, digits, err, err_text)` tuples, a
//! trajectory's table by column. The Python
//! modules next to it (`cylroll/*.py`) give them their classes, docstrings and
//! NumPy arrays.
//!
//! Long computations run on a worker thread with the GIL released while the
//! calling thread waits in slices of 50 ms and checks for signals between
//! them, so Ctrl-C raises `KeyboardInterrupt` at once. The library has no
//! cancellation point, so an interrupted computation finishes on its thread
//! in the background and its answer is dropped. A panic of the library is
//! caught on that thread and raised as `cylroll.InternalError`; it never
//! unwinds into Python.

use cylroll::check::CheckReport;
use cylroll::error::Error;
use cylroll::exact::Exact;
use cylroll::golden::Case;
use cylroll::model::input::{self, Pairs, FRICTION_KEYS, MODEL_KEYS};
use cylroll::model::Model;
use cylroll::motion::{self, Branch};
use cylroll::numeric::verify::Verified;
use cylroll::oracle::{self, Answer, Options, Oracle, FORCES_KEYS};
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::sync::mpsc::{self, RecvTimeoutError};
use std::time::Duration;

/// A verified value as it crosses into Python: name, decimal text (exactly
/// the verified digits), digits verified, error bound (as a float and as
/// short text).
type Value = (String, String, u32, f64, String);

fn value(v: &Verified) -> Value {
    (
        v.name.clone(),
        v.text.clone(),
        v.digits,
        err_f64(v),
        v.err_text(),
    )
}

/// A value's error bound as a float, rounded up: still a bound (and not
/// 0 below binary64's range where the bound is not 0).
fn err_f64(v: &Verified) -> f64 {
    let f = v.err_bound.to_f64();
    if v.err_bound > f {
        // the next float up (f64::next_up is newer than the crates' Rust
        // 1.85): a bound is >= 0, so one more unit of its bits, from 0 the
        // smallest subnormal
        f64::from_bits(f.to_bits() + 1)
    } else {
        f
    }
}

/// A trajectory's table as it crosses into Python, by column (the Python
/// side makes a row's `Value`s only when asked): per column its texts,
/// digits, error bounds and their short texts; the mode of each row.
#[derive(Default)]
struct Table {
    text: Vec<Vec<String>>,
    digits: Vec<Vec<u32>>,
    err: Vec<Vec<f64>>,
    err_text: Vec<Vec<String>>,
    modes: Vec<String>,
}

impl Table {
    /// Appends the rows of a block of the answer.
    fn push(&mut self, a: &Answer) {
        for r in &a.rows {
            let w = r.values.len();
            if self.text.len() < w {
                self.text.resize_with(w, Vec::new);
                self.digits.resize_with(w, Vec::new);
                self.err.resize_with(w, Vec::new);
                self.err_text.resize_with(w, Vec::new);
            }
            for (j, v) in r.values.iter().enumerate() {
                self.text[j].push(v.text.clone());
                self.digits[j].push(v.digits);
                self.err[j].push(err_f64(v));
                self.err_text[j].push(v.err_text());
            }
            self.modes.push(r.phase.tag());
        }
    }
}

/// A model's exact echo (key, text), with the laws (`floor`, `contact`,
/// `mu_floor`, `mu_contact`) first.
type Echo = Vec<(&'static str, String)>;

/// An event as it crosses into Python: kind, contact, mode entered, t, θ.
type Event = (
    String,
    Option<String>,
    Option<String>,
    Value,
    Value,
    Vec<String>,
);

fn values(vs: &[Verified]) -> Vec<Value> {
    vs.iter().map(value).collect()
}

/// A library error as the Python exception of `cylroll._errors` (built there,
/// so the classes can inherit from `ValueError`, `ArithmeticError`, …).
fn py_error(py: Python<'_>, e: &Error) -> PyErr {
    let (kind, fields): (&str, Vec<(&str, String)>) = match e {
        Error::InvalidParameter {
            name,
            value,
            allowed,
        } => (
            "invalid_parameter",
            vec![
                // the keyword's spelling in Python (the library names flags)
                ("name", python_name(name)),
                ("value", value.clone()),
                ("allowed", python_words(allowed)),
            ],
        ),
        Error::NotPhysical { what } => ("not_physical", vec![("what", python_words(what))]),
        Error::NotConverged {
            quantity,
            requested,
            reached,
            detail,
        } => (
            "not_converged",
            vec![
                ("quantity", quantity.clone()),
                ("requested", requested.to_string()),
                ("reached", reached.clone()),
                ("detail", python_words(detail)),
            ],
        ),
        Error::NoSignChange { quantity, lo, hi } => (
            "no_sign_change",
            vec![
                ("quantity", quantity.clone()),
                ("lo", lo.clone()),
                ("hi", hi.clone()),
            ],
        ),
        Error::Io { path, what } => ("io", vec![("path", path.clone()), ("what", what.clone())]),
        Error::Write { path, what } => (
            "write",
            vec![("path", path.clone()), ("what", what.clone())],
        ),
        // only after a KeyboardInterrupt, which the caller has raised already
        Error::Cancelled => ("cancelled", vec![]),
    };
    let build = || -> PyResult<PyErr> {
        let make = py.import("cylroll._errors")?.getattr("_from_library")?;
        let exc = make.call1((kind, python_message(e), e.exit_code(), fields))?;
        Ok(PyErr::from_value(exc))
    };
    build().unwrap_or_else(|err| err)
}

/// A parameter's name as the Python keyword: the command line's `to` (the
/// angle of `time`) is `theta`, a flag's hyphens are underscores.
fn python_name(name: &str) -> String {
    // the keyword alone: a file it was read from (`m1 (in a-b.toml)`) keeps
    // its path as it is
    let (word, rest) = name.split_once(' ').map_or((name, ""), |(w, r)| (w, r));
    let word = match word {
        "to" => "theta".to_string(),
        w => w.replace('-', "_"),
    };
    if rest.is_empty() {
        word
    } else {
        format!("{word} {rest}")
    }
}

/// The command line's flags the library's messages name, and the Python
/// keyword of each (the name with underscores; `--params` is a file read
/// by `Model.from_toml`).
const FLAGS: &[&str] = &[
    "columns",
    "digits",
    "event-tol",
    "golden",
    "max-rows",
    "mu",
    "mu-contact",
    "mu-floor",
    "omega0",
    "part-at",
    "past-end",
    "schema",
    "steps",
    "t-end",
    "theta",
    "theta0",
    "thetadot0",
    "times",
    "times-file",
    "to",
    "tol",
];

/// A library text as a Python user reads it: the command line's flags
/// become the keywords that ask the same (`--branch part` is
/// `branch="part"`, `--part-at` `part_at`, `--digits` `digits`, `--params
/// FILE` `Model.from_toml(FILE)`, …). Only a flag of [`FLAGS`] standing as
/// a word (not inside a path, a column name or a cell quoted: `no--such`)
/// is rewritten; nothing else changes.
fn python_words(text: &str) -> String {
    let text = text
        .replace("--branch part", "branch=\"part\"")
        .replace("past-end '", "past_end='")
        .replace("--params FILE", "Model.from_toml(FILE)");
    let mut out = String::with_capacity(text.len());
    let mut rest = text.as_str();
    while let Some(i) = rest.find("--") {
        let (before, at) = rest.split_at(i);
        out.push_str(before);
        let after = &at[2..];
        let end = after
            .find(|c: char| !(c.is_ascii_lowercase() || c.is_ascii_digit() || c == '-'))
            .unwrap_or(after.len());
        let flag = after[..end].trim_end_matches('-');
        // a word of its own: at the start, or after a space or bracket
        let alone = out
            .chars()
            .last()
            .is_none_or(|c| c.is_whitespace() || "([{,;:'\"`".contains(c));
        if alone && flag == "params" {
            out.push_str("Model.from_toml");
            rest = &after[flag.len()..];
        } else if alone && FLAGS.contains(&flag) {
            out.push_str(&python_name(flag));
            rest = &after[flag.len()..];
        } else {
            out.push_str("--");
            rest = after;
        }
    }
    out.push_str(rest);
    out
}

/// An error's message in Python's words ([`python_words`]; an invalid
/// parameter named by its keyword).
fn python_message(e: &Error) -> String {
    match e {
        Error::InvalidParameter {
            name,
            value,
            allowed,
        } => Error::InvalidParameter {
            name: python_name(name),
            value: value.clone(),
            allowed: python_words(allowed),
        }
        .to_string(),
        // a file's error names its path as it is
        Error::Io { .. } | Error::Write { .. } => e.to_string(),
        other => python_words(&other.to_string()),
    }
}

fn internal(py: Python<'_>, what: String) -> PyErr {
    let build = || -> PyResult<PyErr> {
        let cls = py.import("cylroll._errors")?.getattr("InternalError")?;
        Ok(PyErr::from_value(cls.call1((what.clone(),))?))
    };
    build().unwrap_or_else(|_| PyRuntimeError::new_err(what))
}

fn panic_text(p: Box<dyn std::any::Any + Send>) -> String {
    let msg = p
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| p.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "(no message)".into());
    format!("cylroll panicked (a bug; please report it with the model): {msg}")
}

/// Runs `f` on a worker thread with the GIL released; checks for signals
/// every 50 ms (a `KeyboardInterrupt` returns at once and sets the worker's
/// cancellation flag, [`cylroll::cancel`], so the computation stops at its
/// next rung or step); library errors and panics become Python exceptions.
fn detached<T, F>(py: Python<'_>, f: F) -> PyResult<T>
where
    T: Send + 'static,
    F: FnOnce() -> cylroll::Result<T> + Send + 'static,
{
    let (tx, rx) = mpsc::channel();
    // set on KeyboardInterrupt: the worker stops at its next rung or step
    let cancel = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
    let flag = cancel.clone();
    std::thread::Builder::new()
        .name("cylroll".into())
        .stack_size(64 << 20)
        .spawn(move || {
            // MPFR's per-thread caches outlive the thread otherwise
            let _caches = cylroll::numeric::ThreadCaches;
            cylroll::cancel::install(flag);
            let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(f));
            let _ = tx.send(r);
        })
        .map_err(|e| internal(py, format!("cannot start a worker thread: {e}")))?;
    let mut rx = rx;
    loop {
        let (back, got) = py.detach(move || {
            let r = rx.recv_timeout(Duration::from_millis(50));
            (rx, r)
        });
        rx = back;
        match got {
            Ok(Ok(Ok(v))) => return Ok(v),
            Ok(Ok(Err(e))) => return Err(py_error(py, &e)),
            Ok(Err(p)) => return Err(internal(py, panic_text(p))),
            Err(RecvTimeoutError::Timeout) => {
                if let Err(e) = py.check_signals() {
                    // stop the worker too (it ends at its next check)
                    cancel.store(true, std::sync::atomic::Ordering::Relaxed);
                    return Err(e);
                }
            }
            Err(RecvTimeoutError::Disconnected) => {
                return Err(internal(
                    py,
                    "the worker thread ended without an answer".into(),
                ))
            }
        }
    }
}

/// Runs a quick library call on this thread, with panics caught.
fn direct<T>(py: Python<'_>, f: impl FnOnce() -> cylroll::Result<T>) -> PyResult<T> {
    match std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)) {
        Ok(Ok(v)) => Ok(v),
        Ok(Err(e)) => Err(py_error(py, &e)),
        Err(p) => Err(internal(py, panic_text(p))),
    }
}

/// The model from key/value pairs, exactly as the command line builds it
/// (every contact's law from `floor`, `contact`, `mu_floor`, `mu_contact`).
fn spec(vals: &Pairs) -> cylroll::Result<Model> {
    for k in vals.keys() {
        if !MODEL_KEYS.contains(&k.as_str()) && !FRICTION_KEYS.contains(&k.as_str()) {
            return Err(Error::invalid(
                "model",
                k,
                format!(
                    "unknown key; allowed keys: {}, {}",
                    MODEL_KEYS.join(", "),
                    FRICTION_KEYS.join(", ")
                ),
            ));
        }
    }
    input::model_from_pairs(vals)
}

/// Validates a model; returns its exact echo (key, text) in the library's
/// order, the laws first.
#[pyfunction]
fn validate(py: Python<'_>, pairs: Pairs) -> PyResult<Echo> {
    direct(py, || Ok(spec(&pairs)?.echo()))
}

/// How to answer: digits, and the branch (`stay`, `part`, or an angle to
/// part at).
fn options(digits: u32, branch: &str, part_at: Option<&str>) -> cylroll::Result<Options> {
    let branch = match (part_at, branch) {
        (Some(a), _) => Branch::PartAt(Exact::parse("part_at", a, true)?),
        (None, "stay") => Branch::Stay,
        (None, "part") => Branch::Part,
        (None, other) => {
            return Err(Error::invalid(
                "branch",
                other,
                "expected 'stay' (the contact persists while it can) or 'part' (the cylinders \
                 part at the first instant they may)",
            ))
        }
    };
    Ok(Options {
        digits,
        branch,
        method: motion::Method::Auto,
    })
}

fn events(a: &Answer) -> Vec<Event> {
    a.events
        .iter()
        .map(|e| {
            (
                e.kind.name().to_string(),
                e.which.map(|w| w.name().to_string()),
                e.phase.map(|p| p.tag()),
                value(&e.t),
                value(&e.theta),
                e.also.clone(),
            )
        })
        .collect()
}

/// The parts of an answer every question shares, as a dict: `values`,
/// `notes`, `events`, `start_mode`, `end`, `branch`, `mode` (the phase at an
/// angle), `routes`.
fn answer_dict<'py>(py: Python<'py>, a: &Answer) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("values", values(&a.values))?;
    let notes: Vec<String> = a.notes.iter().map(|n| python_words(n)).collect();
    d.set_item("notes", notes)?;
    d.set_item("events", events(a))?;
    d.set_item("start_mode", a.start_mode.map(|m| m.tag()))?;
    d.set_item("end", a.end.map(|e| e.name()))?;
    d.set_item(
        "impact_surface",
        match a.end {
            Some(motion::End::Impact(s)) => Some(s.name()),
            _ => None,
        },
    )?;
    d.set_item("branch", a.branch.name())?;
    d.set_item("mode", a.phase.map(|p| p.tag()))?;
    d.set_item(
        "routes",
        a.routes.iter().map(|r| r.name()).collect::<Vec<_>>(),
    )?;
    Ok(d)
}

/// The model keys of a TOML file (`--params` format: strings or integers;
/// a golden case file's `description` and `steps` are accepted and ignored).
#[pyfunction]
fn read_toml(py: Python<'_>, path: std::path::PathBuf) -> PyResult<Pairs> {
    direct(py, || {
        let pairs = input::read_params(&path)?;
        // a value out of its range is named with the file, as the command
        // line's --params names it (m1 (in q.toml)), not by the model made
        // from the pairs later
        input::model_from_pairs(&pairs).map_err(|e| input::in_file(e, &path))?;
        Ok(pairs)
    })
}

/// Names of the embedded golden cases, sorted.
#[pyfunction]
fn golden_names() -> Vec<&'static str> {
    cylroll::golden::BUILTIN.iter().map(|(n, _)| *n).collect()
}

fn golden_text(name: &str) -> cylroll::Result<&'static str> {
    cylroll::golden::BUILTIN
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, t)| *t)
        .ok_or_else(|| {
            Error::invalid(
                "case",
                name,
                format!("unknown case; known: {}", golden_names().join(", ")),
            )
        })
}

/// A golden case: its TOML text, the model keys, the description and the
/// number of intervals of its time grid.
#[pyfunction]
fn golden_case(py: Python<'_>, name: &str) -> PyResult<(String, Pairs, String, u32)> {
    direct(py, || {
        let text = golden_text(name)?;
        let (pairs, description, steps) = cylroll::golden::case_text_parts(name, text)?;
        Ok((text.to_string(), pairs, description, steps))
    })
}

fn parse_angle(name: &str, text: &str) -> cylroll::Result<Exact> {
    Exact::parse(name, text, true)
}

/// `separation`: the motion to its end (see [`answer_dict`]).
#[pyfunction]
#[pyo3(signature = (pairs, digits, branch="stay".to_string(), part_at=None))]
fn separation<'py>(
    py: Python<'py>,
    pairs: Pairs,
    digits: u32,
    branch: String,
    part_at: Option<String>,
) -> PyResult<Bound<'py, PyDict>> {
    let a = detached(py, move || {
        let model = spec(&pairs)?;
        oracle::separation(&model, &options(digits, &branch, part_at.as_deref())?)
    })?;
    answer_dict(py, &a)
}

/// `time`: the time at which θ first reaches `theta`, and the mode there.
#[pyfunction]
#[pyo3(signature = (pairs, digits, theta, branch="stay".to_string(), part_at=None))]
fn time<'py>(
    py: Python<'py>,
    pairs: Pairs,
    digits: u32,
    theta: String,
    branch: String,
    part_at: Option<String>,
) -> PyResult<Bound<'py, PyDict>> {
    let a = detached(py, move || {
        let model = spec(&pairs)?;
        let th = parse_angle("theta", &theta)?;
        oracle::time(&model, &th, &options(digits, &branch, part_at.as_deref())?)
    })?;
    answer_dict(py, &a)
}

/// `forces`: the forces, rates, friction needed, slip speeds and work where
/// θ first reaches `theta` (and for the ideal models the most friction
/// needed so far), and the mode there.
#[pyfunction]
#[pyo3(signature = (pairs, digits, theta, branch="stay".to_string(), part_at=None))]
fn forces<'py>(
    py: Python<'py>,
    pairs: Pairs,
    digits: u32,
    theta: String,
    branch: String,
    part_at: Option<String>,
) -> PyResult<Bound<'py, PyDict>> {
    let a = detached(py, move || {
        let model = spec(&pairs)?;
        let th = parse_angle("theta", &theta)?;
        oracle::forces(&model, &th, &options(digits, &branch, part_at.as_deref())?)
    })?;
    answer_dict(py, &a)
}

/// `trajectory`: the answer's dict with `columns`, `cols` (per column:
/// texts, digits, error bounds, their short texts; see [`Table`]) and
/// `modes` (the phase of each row).
#[pyfunction]
#[pyo3(signature = (pairs, digits, times, branch="stay".to_string(), part_at=None, columns=None))]
fn trajectory<'py>(
    py: Python<'py>,
    pairs: Pairs,
    digits: u32,
    times: Vec<String>,
    branch: String,
    part_at: Option<String>,
    columns: Option<String>,
) -> PyResult<Bound<'py, PyDict>> {
    let a = detached(py, move || {
        let model = spec(&pairs)?;
        let times: Vec<Exact> = times
            .iter()
            .map(|t| Exact::parse("times", t, false))
            .collect::<cylroll::Result<_>>()?;
        if times.is_empty() {
            return Err(Error::invalid("times", "", "give at least one time"));
        }
        let cols = match &columns {
            Some(c) => oracle::parse_columns(c)?,
            None => oracle::all_columns(),
        };
        // in blocks of rows, as the command line streams a long table: the
        // library's working numbers for one block at a time, the table kept
        // as text and floats
        let mut table = Table::default();
        let head = oracle::trajectory_in_blocks(
            &model,
            &times,
            &options(digits, &branch, part_at.as_deref())?,
            &cols,
            BLOCK_ROWS,
            |_, block| {
                table.push(&block);
                Ok(())
            },
        )?;
        Ok((head, table))
    })?;
    let (a, table) = a;
    let d = answer_dict(py, &a)?;
    let numeric: Vec<&String> = a.columns.iter().filter(|c| *c != "mode").collect();
    let n = numeric.len();
    d.set_item("columns", numeric)?;
    let Table {
        text,
        digits,
        err,
        err_text,
        modes,
    } = table;
    let mut cols = Vec::with_capacity(n);
    for (((t, g), e), et) in text.into_iter().zip(digits).zip(err).zip(err_text) {
        cols.push((t, g, e, et));
    }
    d.set_item("cols", cols)?;
    d.set_item("modes", modes)?;
    Ok(d)
}

/// Rows of a trajectory computed at once (the command line's block).
const BLOCK_ROWS: usize = 2000;

/// An enclosure as the Python side takes it: (name, proved text, proved
/// digits, mid, rad), the printed [mid ± rad] containing the enclosure.
type Enclosure = (String, String, u32, String, String);

/// One proved value as the Python side takes it.
fn enclosure(v: &cylroll::oracle::rigorous::Proved, digits: u32) -> Enclosure {
    let (mid, rad) = v.texts(digits);
    (
        v.name.clone(),
        v.shown.text.clone(),
        v.shown.digits,
        mid,
        rad,
    )
}

/// `enclose`: proved enclosures (`--rigorous`) of the ideal models'
/// `separation` (θs, t_s, and θ*, t* where the motion is not unique), `time` (t) or `forces` at `theta`, and with
/// friction of where sticking ends (`separation`: θ and t of the first slip
/// onset, or θs and t_s when the contact opens there); a quantity that
/// cannot be enclosed is left out (its verified value is elsewhere).
#[pyfunction]
#[pyo3(signature = (pairs, digits, what, theta=None))]
fn enclose(
    py: Python<'_>,
    pairs: Pairs,
    digits: u32,
    what: String,
    theta: Option<String>,
) -> PyResult<Vec<Enclosure>> {
    detached(py, move || {
        let model = spec(&pairs)?;
        match (what.as_str(), theta.is_some()) {
            ("separation", false) | ("time", true) | ("forces", true) => {}
            _ => {
                return Err(Error::invalid(
                    "what",
                    &what,
                    "expected separation (no theta), or time or forces with theta",
                ))
            }
        }
        let Some(ideal) = model.ideal() else {
            // with friction: where sticking ends, from a start where both
            // contacts stick (the command line's separation --rigorous)
            if what != "separation" || theta.is_some() {
                // the keyword that asked it (the command line names its flag)
                return Err(cylroll::oracle::rigorous::unsupported("with friction")
                    .map_invalid(|_, v| ("what".to_string(), format!("{what} {v}"))));
            }
            let ans = oracle::separation(&model, &Options::digits(digits))?;
            let slots = cylroll::oracle::rigorous::stick_end_proved(&model, &ans, digits).map_err(
                |why| Error::not_physical(format!("with friction nothing is enclosed: {why}")),
            )?;
            return Ok(slots
                .into_iter()
                .filter_map(|(_, _, pv)| pv)
                .map(|v| enclosure(&v, digits))
                .collect());
        };
        let mut o = Oracle::new(&ideal, digits)?;
        let th = theta.map(|t| parse_angle("theta", &t)).transpose()?;
        // the branch point's verified angle, the start of its proof (the
        // command line's separation --rigorous encloses it too)
        let branch_start = if th.is_none() {
            o.branch_point()?.map(|v| v.value)
        } else {
            None
        };
        // the command line's retry: twice the precision where digits fall
        // short, the first result kept if the second fails
        let proved = cylroll::oracle::rigorous::prove_with(
            digits,
            |p| -> cylroll::Result<Vec<cylroll::oracle::rigorous::Proved>> {
                Ok(match &th {
                    None => {
                        let (a, b) = o.rigorous_separation(p)?;
                        // θ*, t* where the motion is not unique (left out
                        // when the proof does not close, like every value)
                        let star = match &branch_start {
                            Some(start) => match o.rigorous_branch_point(start, &a.iv, p) {
                                Ok((th, t)) => std::iter::once(th).chain(t.ok()).collect(),
                                Err(_) => Vec::new(),
                            },
                            None => Vec::new(),
                        };
                        std::iter::once(a).chain(b.ok()).chain(star).collect()
                    }
                    Some(t) if what == "time" => vec![o.rigorous_time(t, p)?],
                    Some(t) => o.rigorous_forces(t, p)?.into_iter().flatten().collect(),
                })
            },
            |proved| {
                proved
                    .iter()
                    .any(|v| v.shown.digits < digits && v.shown.text != "0")
            },
        )?;
        let out = proved.iter().map(|v| enclosure(v, digits)).collect();
        Ok(out)
    })
}

/// The one call into the library's candidate judge (`cylroll check`): the
/// candidate as CSV text or a file path (read twice where the branch is
/// found from it), the limits built from the keyword arguments.
fn run_check(
    csv: Option<String>,
    path: Option<String>,
    source: &str,
    case: &Case,
    lim: &cylroll::check::Limits,
) -> cylroll::Result<CheckReport> {
    match (csv, path) {
        (Some(text), _) => {
            let src = cylroll::check::Text {
                text: &text,
                name: source.to_string(),
            };
            cylroll::check::check_source(&src, case, lim)
        }
        (None, Some(p)) => cylroll::check::check_source(&cylroll::check::File::new(p), case, lim),
        (None, None) => Err(Error::invalid("candidate", "", "give CSV text or a path")),
    }
}

/// A tolerance override (column, rtol, atol or None), each number as the
/// decimal text Python gave (read as the command line's `--tol`).
type TolOverride = (String, String, Option<String>);

/// `check`: judges a candidate (CSV text, or the path of a CSV file)
/// against a golden case (by name) or a model (key/value pairs) with the
/// command line's scoring core; returns `{"report": JSON text with numbers,
/// "text": the table, "passed": bool, "verdict": "pass" | "fail" |
/// "undecided"}`.
#[pyfunction]
#[pyo3(signature = (csv, path, source, case_name, pairs, rtol, atol, tols, branch, part_at, event_tol, digits, past_end, max_rows, schema=None))]
#[allow(clippy::too_many_arguments)]
fn check<'py>(
    py: Python<'py>,
    csv: Option<String>,
    path: Option<String>,
    source: String,
    case_name: String,
    pairs: Option<Pairs>,
    rtol: String,
    atol: String,
    tols: Vec<TolOverride>,
    branch: String,
    part_at: Option<String>,
    event_tol: Option<String>,
    digits: u32,
    past_end: String,
    max_rows: Option<usize>,
    schema: Option<u32>,
) -> PyResult<Bound<'py, PyDict>> {
    use cylroll::check::{BranchRequest, Limits, PastEnd};
    let rep = detached(py, move || {
        let (pairs, description, steps) = match pairs {
            Some(p) => (p, String::new(), 40),
            None => cylroll::golden::case_text_parts(&case_name, golden_text(&case_name)?)?,
        };
        let model = spec(&pairs)?;
        let case = Case {
            name: case_name,
            description,
            model,
            steps,
        };
        let mut lim = Limits::new(
            cylroll::check::tolerance("rtol", &rtol)?,
            cylroll::check::tolerance("atol", &atol)?,
            digits,
        );
        lim.tols = tols
            .into_iter()
            .map(|(column, rtol, atol)| {
                let name = format!("tol['{column}']");
                cylroll::check::tolerance(&name, &rtol)?;
                let spec = match atol {
                    Some(a) => {
                        cylroll::check::tolerance(&name, &a)?;
                        format!("{column}={rtol},{a}")
                    }
                    None => format!("{column}={rtol}"),
                };
                // the command line's reading: a known column, tolerances as `tolerance`
                cylroll::check::parse_override(&spec)
            })
            .collect::<cylroll::Result<_>>()?;
        if let Some(n) = max_rows {
            if !(1..=100_000_000).contains(&n) {
                return Err(Error::invalid(
                    "max_rows",
                    n,
                    "must be between 1 and 100000000",
                ));
            }
            lim.max_rows = n;
        }
        lim.branch = match (part_at, branch.as_str()) {
            (Some(a), _) => BranchRequest::PartAt(Exact::parse("part_at", &a, true)?),
            (None, "auto") => BranchRequest::Auto,
            (None, "stay") => BranchRequest::Stay,
            (None, "part") => BranchRequest::Part,
            (None, other) => {
                return Err(Error::invalid(
                    "branch",
                    other,
                    "expected 'auto' (the branch the candidate took), 'stay' or 'part'",
                ))
            }
        };
        if let Some(e) = event_tol {
            lim.event_tol = cylroll::check::tolerance("event_tol", &e)?;
        }
        lim.past_end = PastEnd::parse("past_end", &past_end)?;
        if let Some(v) = schema {
            if !(1..=2).contains(&v) {
                return Err(Error::invalid("schema", v, "expected 1 or 2"));
            }
            lim.schema = Some(v);
        }
        run_check(csv, path, &source, &case, &lim)
    })?;
    let d = PyDict::new(py);
    d.set_item("passed", rep.passed())?;
    d.set_item("verdict", rep.verdict())?;
    d.set_item("text", python_words(&rep.text()))?;
    d.set_item("report", rep.value(false).to_string())?;
    Ok(d)
}

/// The native module.
#[pymodule]
fn _cylroll(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("MODEL_KEYS", MODEL_KEYS.to_vec())?;
    m.add("FRICTION_KEYS", FRICTION_KEYS.to_vec())?;
    m.add("COLUMNS", motion::COLUMNS.to_vec())?;
    m.add("FORCE_KEYS", FORCES_KEYS.to_vec())?;
    m.add("MAX_DIGITS", cylroll::oracle::MAX_DIGITS)?;
    m.add("MAX_ROWS", cylroll::check::MAX_ROWS_LIMIT)?;
    m.add("LIBRARY_VERSION", env!("CARGO_PKG_VERSION"))?;
    m.add_function(wrap_pyfunction!(validate, m)?)?;
    m.add_function(wrap_pyfunction!(read_toml, m)?)?;
    m.add_function(wrap_pyfunction!(golden_names, m)?)?;
    m.add_function(wrap_pyfunction!(golden_case, m)?)?;
    m.add_function(wrap_pyfunction!(separation, m)?)?;
    m.add_function(wrap_pyfunction!(time, m)?)?;
    m.add_function(wrap_pyfunction!(forces, m)?)?;
    m.add_function(wrap_pyfunction!(trajectory, m)?)?;
    m.add_function(wrap_pyfunction!(check, m)?)?;
    m.add_function(wrap_pyfunction!(enclose, m)?)?;
    Ok(())
}
