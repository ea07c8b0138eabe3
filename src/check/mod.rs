//! `cylroll check`: hold another program's table against the oracle — the
//! one scoring core of the command line's `check`, Python's `cylroll.check`
//! and the engine-conformance scorecard.
//!
//! The candidate's columns are matched by header (any subset of the golden
//! columns and `mode`; `t` is required); the oracle is evaluated at the
//! candidate's own times (no interpolation of either side), in chunks of
//! [`CHUNK_ROWS`] rows. A value fails when |candidate − oracle| > atol +
//! rtol·|oracle| (numpy's `isclose` rule), with a tolerance per column
//! ([`tol`]: atol in units of the column's natural scale unless `--tol` sets
//! it). The verdict comes
//!
//! - per column (the largest errors and where, the first failing row);
//! - per phase of the reference (a new phase each time the mode of the
//!   oracle's rows changes: `stick/stick`, `stick/slip+`, `flight`, …);
//! - per event, when the candidate has a `mode` column: its transitions
//!   (the last row in the old mode, the first in the new) are matched with
//!   the reference's events entering the same mode, in order; the error is
//!   in θ: the oracle's θ at the nearer end of the candidate's bracket minus
//!   the event's θ (0 when the event lies inside the bracket), judged against
//!   `event_tol` (radians; default [`DEFAULT_EVENT_TOL`]);
//! - per branch where the motion is not unique ([`branch`]): under `auto`
//!   the candidate is read twice, first to find where it parted, then
//!   judged against the lawful branch it took (or failed where it parted
//!   where the rigid-body motion may not).

pub mod branch;
mod events;
pub mod read;
mod render;
pub mod tol;

/// The largest `max_rows` a candidate may be given (`--max-rows`).
pub const MAX_ROWS_LIMIT: usize = 100_000_000;

pub use branch::{BranchReport, Parting, Request as BranchRequest};
pub use read::{File, Source, Text, MAX_LINE_BYTES};
pub use tol::{parse_override, tolerance, tolerance_of, Override, Tol, TOLERANCE_ALLOWED};

use crate::error::{Error, Result};
use crate::exact::Exact;
use crate::golden::Case;
use crate::motion::Branch;
use crate::oracle::{Options, Row};
use read::{Cell, Rows};
use rug::Float;

/// The columns a candidate may have: every trajectory column and `mode`.
pub fn known_columns() -> Vec<&'static str> {
    let mut k = crate::motion::COLUMNS.to_vec();
    k.push("mode");
    k
}

/// The index of the `mode` column in [`known_columns`].
pub const MODE: usize = crate::motion::COLUMNS.len();

/// Whether a candidate's mode cell names the reference's mode `reference`:
/// the same text, or per contact an unsigned `slip` where the reference
/// slides either way (an engine that does not sign its slip wrote `slip`,
/// and every sliding row failed against `slip+`). A signed slide against
/// the reference's unsigned frictionless one does not match: its sign is
/// not checked there, and a wrong sign would pass.
pub fn mode_matches(cand: &str, reference: &str) -> bool {
    if cand == reference {
        return true;
    }
    match (cand.split_once('/'), reference.split_once('/')) {
        (Some((cf, cc)), Some((rf, rc))) => {
            let one = |c: &str, r: &str| c == r || (c == "slip" && r.starts_with("slip"));
            one(cf, rf) && one(cc, rc)
        }
        _ => false,
    }
}

/// The index of `theta` in [`crate::motion::COLUMNS`].
const THETA: usize = 1;

/// The smallest nonzero rtol the oracle's `digits` significant digits can
/// judge: 10^(2 − digits) (a d-digit value is good to 10^(1 − d) relative at
/// worst; a tolerance ten times that keeps the verdict off its last digit).
pub fn finest_rtol(digits: u32) -> f64 {
    10f64.powi(2 - digits as i32)
}

/// Rows evaluated by the oracle at once: memory stays bounded by this many
/// rows whatever the candidate's length.
pub const CHUNK_ROWS: usize = 4096;

/// Default largest number of data rows.
pub const DEFAULT_MAX_ROWS: usize = 1_000_000;

/// Default tolerance of an event, in radians of θ: about what a time-stepper
/// at dt = 1e-3 resolves in the built-in cases (θ̇ dt ≈ 5e-4 near their
/// events). An event whose reference time lies inside the candidate's
/// bracket passes whatever the tolerance.
pub const DEFAULT_EVENT_TOL: f64 = 1e-3;

/// Candidate transitions (changes of its `mode`) kept for matching; more
/// are counted.
pub const MAX_TRANSITIONS: usize = 10_000;

/// What to do with candidate rows after the end of the model on the branch
/// followed (its first impact or a lift-off), where the reference ends.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum PastEnd {
    /// Leave them out, count them and report the first (`rows_after_end`):
    /// an engine that runs on past the impact is judged up to it.
    #[default]
    Report,
    /// Refuse the candidate, naming the first such row.
    Refuse,
}

impl PastEnd {
    /// `report` or `refuse`.
    pub fn parse(name: &str, text: &str) -> Result<Self> {
        match text.trim() {
            "report" => Ok(PastEnd::Report),
            "refuse" => Ok(PastEnd::Refuse),
            _ => Err(crate::error::Error::invalid(
                name,
                text,
                "expected 'report' (leave rows after the end of the model out and report them) \
                 or 'refuse' (refuse the candidate)",
            )),
        }
    }
}

/// The tolerances and limits of a check.
#[derive(Debug, Clone)]
pub struct Limits {
    /// Relative tolerance of every column.
    pub rtol: f64,
    /// Absolute tolerance of every column, in units of its natural scale.
    pub atol: f64,
    /// Per-column overrides (`--tol COLUMN=RTOL[,ATOL]`).
    pub tols: Vec<Override>,
    /// Significant digits of the oracle values.
    pub digits: u32,
    /// Largest number of data rows accepted.
    pub max_rows: usize,
    /// The candidate's schema: 1 (φ2 in the paper's gauge), 2, or `None`
    /// (2, unless the header is exactly a full schema-1 column list).
    pub schema: Option<u32>,
    /// The branch to judge against.
    pub branch: BranchRequest,
    /// Tolerance of an event, in radians of θ.
    pub event_tol: f64,
    /// Rows after the end of the model.
    pub past_end: PastEnd,
}

impl Limits {
    /// `rtol`, `atol` (in units of each column's scale) and `digits`; the
    /// defaults otherwise (auto branch, [`DEFAULT_EVENT_TOL`],
    /// [`DEFAULT_MAX_ROWS`]).
    pub fn new(rtol: f64, atol: f64, digits: u32) -> Self {
        Limits {
            rtol,
            atol,
            tols: Vec::new(),
            digits,
            max_rows: DEFAULT_MAX_ROWS,
            schema: None,
            branch: BranchRequest::Auto,
            event_tol: DEFAULT_EVENT_TOL,
            past_end: PastEnd::Refuse,
        }
    }
}

/// One column's statistics over one phase.
#[derive(Debug, Clone, Default)]
pub struct PhaseColumn {
    /// Largest absolute error (0 for `mode`).
    pub max_abs: f64,
    /// Time where it occurs (`-` before any row).
    pub max_abs_t: String,
    /// Rows exceeding the tolerance (`mode`: rows in another mode).
    pub failures: usize,
    /// Largest |err| / limit there.
    pub worst_ratio: f64,
    /// Values whose verdict the oracle's error bound leaves open.
    pub undecided: usize,
}

/// Per-column statistics.
#[derive(Debug, Clone)]
pub struct ColumnStats {
    /// Column name.
    pub name: String,
    /// Largest absolute error.
    pub max_abs: f64,
    /// Time where it occurs.
    pub max_abs_t: String,
    /// Largest relative error |err|/|oracle| (`None` when every oracle value
    /// of the column is 0, where a relative error is undefined).
    pub max_rel: Option<f64>,
    /// Time where it occurs.
    pub max_rel_t: String,
    /// Largest |err| / (atol + rtol·|oracle|): above 1 fails.
    pub worst_ratio: f64,
    /// Which term of the limit was the larger where `worst_ratio` occurs:
    /// `"atol"` (an oracle value near 0) or `"rtol"`.
    pub worst_bound: &'static str,
    /// Rows exceeding the tolerance.
    pub failures: usize,
    /// Values whose verdict is open: |err| is within the oracle's error
    /// bound of the limit, so the verdict would rest on unverified digits.
    pub undecided: usize,
    /// The tolerance applied (None for `mode`).
    pub tol: Option<Tol>,
    /// Per phase of [`CheckReport::phases`], in order.
    pub phases: Vec<PhaseColumn>,
}

/// The first value out of tolerance (or, for [`CheckReport::first_undecided`],
/// whose verdict is open).
#[derive(Debug, Clone)]
pub struct FirstFailure {
    /// 1-based data row of the candidate file.
    pub row: usize,
    /// Its time.
    pub t: String,
    /// The column.
    pub column: String,
    /// The candidate's value as written.
    pub candidate: String,
    /// The oracle's value (verified digits).
    pub oracle: String,
    /// The limit atol + rtol·|oracle| it exceeded.
    pub limit: f64,
    /// Which term of the limit was the larger (`"atol"` or `"rtol"`; `"mode"`).
    pub bound: &'static str,
}

/// A phase of the reference on the candidate's grid: consecutive rows the
/// oracle puts in the same mode.
#[derive(Debug, Clone)]
pub struct PhaseInfo {
    /// The mode tag (`stick/slip+`, `flight`).
    pub tag: String,
    /// Time of its first and last row.
    pub t_first: String,
    /// Time of its last row.
    pub t_last: String,
    /// Those times as f64.
    pub t_first_f: f64,
    /// The last time as f64.
    pub t_last_f: f64,
    /// 1-based candidate rows of its first and last row.
    pub row_first: usize,
    /// Its last row.
    pub row_last: usize,
    /// Rows in it.
    pub rows: usize,
}

/// A change of the candidate's `mode` between two consecutive rows.
#[derive(Debug, Clone)]
pub struct Transition {
    /// The mode left.
    pub from: String,
    /// The mode entered.
    pub to: String,
    /// 1-based rows: the last in the old mode, the first in the new.
    pub rows: (usize, usize),
    /// Their times (as the candidate wrote them, read exactly).
    pub t: (String, String),
    /// Those times as f64.
    pub t_f: (f64, f64),
    /// The oracle's θ there (on the branch followed).
    pub theta: (f64, f64),
}

/// The verdict on one event of the reference (or one transition of the
/// candidate the reference does not have).
#[derive(Debug, Clone)]
pub struct EventVerdict {
    /// `slip_onset`, `separation`, …; `spurious` for a transition of the
    /// candidate the reference does not have.
    pub kind: String,
    /// `floor` or `contact`, where the event concerns one.
    pub contact: Option<String>,
    /// The mode entered (`flight`, `stick/slip+`; `-` at the end of the model).
    pub mode: String,
    /// The reference's time and θ (verified digits; None for `spurious`).
    pub reference: Option<(String, String)>,
    /// The same as f64.
    pub reference_f: Option<(f64, f64)>,
    /// The candidate's transition matched with it.
    pub candidate: Option<Transition>,
    /// The error in θ (see the module's documentation).
    pub error: Option<f64>,
    /// The verdict (None: not judged).
    pub passed: Option<bool>,
    /// Why, in words.
    pub why: String,
}

/// The events' verdicts.
#[derive(Debug, Clone, Default)]
pub struct Events {
    /// Whether the events were judged (the candidate has a `mode` column).
    pub judged: bool,
    /// A note (why they are not judged).
    pub note: String,
    /// The reference's events in order (then the candidate's unmatched
    /// transitions).
    pub list: Vec<EventVerdict>,
    /// The candidate's transitions (changes of mode).
    pub transitions: usize,
    /// Unmatched transitions not listed (beyond the first 20).
    pub unlisted: usize,
}

/// The verdict on a candidate file.
#[derive(Debug, Clone)]
pub struct CheckReport {
    /// The case checked against.
    pub case: String,
    /// Relative tolerance of the columns not set by `--tol`.
    pub rtol: f64,
    /// Absolute tolerance of those columns, in units of each column's scale.
    pub atol: f64,
    /// Tolerance of an event, radians of θ.
    pub event_tol: f64,
    /// Data rows read.
    pub rows: usize,
    /// Rows left out after the end of the model ([`PastEnd::Report`]).
    pub rows_after_end: usize,
    /// The first of them: its row and time.
    pub first_after_end: Option<(usize, String)>,
    /// The end of the model on the branch followed: the event (`impact`,
    /// `lift_off`) and its time (verified digits).
    pub end: Option<(String, String)>,
    /// The first value whose verdict is open (see [`ColumnStats::undecided`]).
    pub first_undecided: Option<FirstFailure>,
    /// Column statistics in the candidate's column order (without `t`).
    pub columns: Vec<ColumnStats>,
    /// The first failing value, if any.
    pub first_failure: Option<FirstFailure>,
    /// Significant digits of the oracle values used.
    pub digits: u32,
    /// The branch followed and why.
    pub branch: BranchReport,
    /// The reference's phases on the candidate's grid.
    pub phases: Vec<PhaseInfo>,
    /// The events.
    pub events: Events,
    /// Remarks on the judgement (e.g. a φ2 that fails in a schema-1-like
    /// candidate: `--schema 1`).
    pub notes: Vec<String>,
}

impl CheckReport {
    /// Whether every value is within tolerance (certainly: no verdict left
    /// open by the oracle's error bound), every judged event within
    /// `event_tol` and the branch lawful.
    pub fn passed(&self) -> bool {
        self.failed_definitely().is_none() && self.first_undecided.is_none()
    }

    /// Whether something certainly fails: a value, an event or the branch
    /// (its name); None otherwise.
    pub fn failed_definitely(&self) -> Option<&'static str> {
        if self.first_failure.is_some() {
            Some("value")
        } else if !self.branch.lawful {
            Some("branch")
        } else if self.events.list.iter().any(|e| e.passed == Some(false)) {
            Some("event")
        } else {
            None
        }
    }

    /// The command line's exit status: 0 passed, 1 something fails, 3 no
    /// failure but a verdict the oracle's digits leave open.
    pub fn exit_code(&self) -> i32 {
        if self.failed_definitely().is_some() {
            1
        } else if self.first_undecided.is_some() {
            3
        } else {
            0
        }
    }

    /// Whether phase `k` passes (every column certainly within tolerance there).
    pub fn phase_passed(&self, k: usize) -> bool {
        self.columns.iter().all(|c| {
            c.phases
                .get(k)
                .is_none_or(|p| p.failures == 0 && p.undecided == 0)
        })
    }

    /// A column's statistics.
    pub fn column(&self, name: &str) -> Option<&ColumnStats> {
        self.columns.iter().find(|c| c.name == name)
    }
}

/// Checks the CSV text `csv` (named `source` in messages) against `case`
/// with one rtol, atol (in units of each column's scale) and the defaults
/// otherwise ([`Limits::new`]).
pub fn check(
    csv: &str,
    source: &str,
    case: &Case,
    rtol: f64,
    atol: f64,
    digits: u32,
) -> Result<CheckReport> {
    let src = Text {
        text: csv,
        name: source.to_string(),
    };
    check_source(&src, case, &Limits::new(rtol, atol, digits))
}

/// The previous row of pass 2 (for the candidate's transitions).
struct Prev {
    row: usize,
    t: String,
    t_f: f64,
    mode: Option<String>,
    theta: f64,
}

/// The state of pass 2.
struct Judge<'a> {
    tols: &'a [Tol],
    phi2_shift: Float,
    stats: Vec<ColumnStats>,
    first: Option<FirstFailure>,
    first_undecided: Option<FirstFailure>,
    phases: Vec<PhaseInfo>,
    transitions: Vec<Transition>,
    n_transitions: usize,
    prev: Option<Prev>,
    mode_at: Option<usize>,
    /// The reference's changes of mode on the branch followed: θ there, the
    /// mode before and the mode after (a row's `mode` within `event_tol` of
    /// one may read either: the event's own verdict judges its place).
    changes: Vec<(f64, String, String)>,
    /// `--event-tol`, radians of θ.
    event_tol: f64,
}

/// A chunk of candidate rows: (row, t, cells).
type Chunk = Vec<(read::RowLabel, Exact, Vec<Cell>)>;

/// An error of the oracle on a chunk of rows, naming the candidate and the
/// row (the row whose time the message quotes, else the chunk's rows).
fn at_rows(e: Error, source: &str, chunk: &Chunk) -> Error {
    // "rows 3-7", with the lines where the rows have them: "rows 3-7 (lines 5-9)"
    let span = match (chunk.first(), chunk.last()) {
        (Some(a), Some(b)) => {
            let (a, b) = (a.0, b.0);
            match (a.line(), b.line()) {
                (Some(la), Some(lb)) => format!("rows {}-{} (lines {la}-{lb})", a.row, b.row),
                _ => format!("rows {}-{}", a.row, b.row),
            }
        }
        _ => "rows 0-0".to_string(),
    };
    let rows = |value: &str| {
        chunk
            .iter()
            .find(|c| c.1.to_string() == value)
            .map_or(span.clone(), |c| format!("row {}", c.0))
    };
    let e = e.map_invalid(|name, value| {
        (
            format!("{name} (candidate {source}, {})", rows(&value)),
            value,
        )
    });
    let e = e.map_not_converged(|q, d| (format!("candidate {source}, {span}: {q}"), d));
    match e {
        Error::NotPhysical { what } => Error::NotPhysical {
            what: format!("candidate {source}, {span}: {what}"),
        },
        other => other,
    }
}

/// Checks the candidate `src` against `case` with the tolerances and limits
/// `lim`: under [`BranchRequest::Auto`] where the motion is not unique the
/// candidate is read twice (first to find where it parted), else once; the
/// oracle is evaluated in chunks of [`CHUNK_ROWS`] rows, so memory does not
/// grow with the number of rows.
///
/// Errors (each naming the candidate, and the row where one is at fault): a
/// malformed candidate (header, fields, numbers, times before 0 or out of
/// order), more rows than `lim.max_rows`, a tolerance that is negative or
/// not finite, names a column the candidate lacks or is tighter than the
/// oracle's digits can judge ([`finest_rtol`]), nothing to compare, rows after the
/// end of the model under [`PastEnd::Refuse`] (or every row after it), a
/// failure of the oracle.
pub fn check_source(src: &dyn Source, case: &Case, lim: &Limits) -> Result<CheckReport> {
    let digits = lim.digits;
    let tols = tol::tolerances(&case.model, lim.rtol, lim.atol, &lim.tols)?;
    if !lim.event_tol.is_finite() || lim.event_tol < 0.0 {
        return Err(Error::invalid(
            "event-tol",
            lim.event_tol,
            "must be a finite number >= 0 (radians of theta)",
        ));
    }
    // the header first, and the number of rows: a malformed or too long
    // candidate is refused before any oracle work
    let header = Rows::open(src, case, lim)?.header;
    Rows::open(src, case, lim)?.count_within_limit()?;
    for o in &lim.tols {
        let gi = crate::motion::COLUMNS.iter().position(|c| *c == o.column);
        if !gi.is_some_and(|g| header.has(g)) {
            return Err(Error::invalid(
                "tol",
                format!("{}={}", o.column, o.rtol),
                format!(
                    "names a column {} does not have (its columns: {})",
                    if src.name() == "candidate" {
                        "the candidate".to_string()
                    } else {
                        format!("the candidate {}", src.name())
                    },
                    header.cols.join(", ")
                ),
            ));
        }
    }
    // a relative tolerance finer than the oracle's digits would judge
    // against digits nobody verified
    let finest = finest_rtol(digits);
    for (gi, t) in tols.iter().enumerate().skip(1) {
        if header.has(gi) && t.rtol > 0.0 && t.rtol < finest * (1.0 - 1e-9) {
            let (name, value) = if t.set {
                (
                    "tol",
                    format!("{}={:e}", crate::motion::COLUMNS[gi], t.rtol),
                )
            } else {
                ("rtol", format!("{:e}", t.rtol))
            };
            let need = (2.0 - t.rtol.log10()).ceil() as u32;
            return Err(Error::invalid(
                name,
                value,
                format!(
                    "is tighter than the oracle's {digits} significant digits can judge (a \
                     {digits}-digit value is good to 1e{} relative): give --digits {need} or \
                     more{}",
                    1 - digits as i32,
                    // (an rtol of 1 or more judges nothing: not offered)
                    if digits > 2 {
                        format!(", or an rtol of at least 1e{}", 2 - digits as i32)
                    } else {
                        String::new()
                    }
                ),
            ));
        }
    }
    let opts = |branch: Branch| Options {
        digits,
        branch,
        method: crate::motion::Method::Auto,
    };
    let stay = crate::oracle::separation(&case.model, &opts(Branch::Stay))?;
    let branch = branch::decide(src, case, lim, &stay, &tols)?;
    let followed = if branch.followed == Branch::Stay {
        stay
    } else {
        crate::oracle::separation(&case.model, &opts(branch.followed.clone()))?
    };
    let end_event = followed.events.iter().find(|e| e.phase.is_none());
    let end = end_event.map(|e| (e.kind.name().to_string(), e.t.text.clone()));
    // a row is after the end when its time exceeds the end's by more than
    // the end's error bound, and is not the end to the digits asked (the
    // end's time as printed, given back, is the state there, as the
    // trajectory answers it: it was refused as after the end); nearer ones
    // are the oracle's to place. The rule is trajectory's (`within_digits`)
    // without its time-scale term: the window is never wider than the one
    // trajectory answers in, so no row kept is refused there
    let t_end = end_event.map(|e| {
        let p = e.t.value.prec();
        (
            Float::with_val(p, &e.t.value + &e.t.err_bound),
            e.t.value.clone(),
        )
    });
    let after = |t: &Exact, (te, end): &(Float, Float)| {
        let tf = t.to_float(te.prec());
        tf > *te && !crate::motion::sides::within_digits(&tf, end, digits, &Float::new(te.prec()))
    };

    let mut rows = Rows::open(src, case, lim)?;
    let h = rows.header.clone();
    let mut judge = Judge {
        tols: &tols,
        phi2_shift: h.phi2_shift.clone(),
        stats: h
            .cols
            .iter()
            .zip(&h.idx)
            .filter(|(c, _)| c.as_str() != "t")
            .map(|(c, &gi)| ColumnStats {
                name: c.clone(),
                max_abs: 0.0,
                max_abs_t: "-".into(),
                max_rel: None,
                max_rel_t: "-".into(),
                worst_ratio: 0.0,
                worst_bound: "-",
                failures: 0,
                undecided: 0,
                tol: (gi != MODE).then(|| tols[gi]),
                phases: Vec::new(),
            })
            .collect(),
        first: None,
        first_undecided: None,
        phases: Vec::new(),
        transitions: Vec::new(),
        n_transitions: 0,
        prev: None,
        mode_at: h.idx.iter().filter(|&&i| i != 0).position(|&i| i == MODE),
        changes: {
            let mut before = followed.start_mode.map(|m| m.tag());
            let mut out = Vec::new();
            for e in &followed.events {
                let after = e.phase.as_ref().map(|p| p.tag());
                if let (Some(b), Some(a)) = (&before, &after) {
                    if b != a {
                        out.push((e.theta.value.to_f64(), b.clone(), a.clone()));
                    }
                }
                if after.is_some() {
                    before = after;
                }
            }
            out
        },
        event_tol: lim.event_tol,
    };
    let mut after_end = 0usize;
    let mut first_after_end: Option<(usize, String)> = None;
    let mut chunk: Chunk = Vec::with_capacity(CHUNK_ROWS);
    let trajectory_opts = opts(branch.followed.clone());
    let flush = |chunk: &mut Chunk, judge: &mut Judge| -> Result<()> {
        if chunk.is_empty() {
            return Ok(());
        }
        crate::cancel::check()?;
        let times: Vec<Exact> = chunk.iter().map(|d| d.1.clone()).collect();
        let orows = crate::oracle::trajectory(&case.model, &times, &trajectory_opts)
            .map_err(|e| at_rows(e, src.name(), chunk))?
            .rows;
        for ((row, t, vals), orow) in chunk.iter().zip(&orows) {
            judge.row(row.row, t, vals, orow)?;
        }
        chunk.clear();
        Ok(())
    };
    while let Some((row, t, cells)) = rows.next_row()? {
        if let (Some(te), Some((kind, te_text))) = (&t_end, &end) {
            if after(&t, te) {
                if lim.past_end == PastEnd::Refuse {
                    return Err(read::refuse(
                        src.name(),
                        format!(
                            "row {}: t = {t} is after the end of the model (the {kind} at t = \
                             {te_text} on the {} branch), where the reference ends (past-end \
                             'report' leaves such rows out and reports them)",
                            rows.label(),
                            branch.followed.name()
                        ),
                    ));
                }
                after_end += 1;
                if first_after_end.is_none() {
                    first_after_end = Some((row, t.to_string()));
                }
                continue;
            }
        }
        chunk.push((rows.label(), t, cells));
        if chunk.len() == CHUNK_ROWS {
            flush(&mut chunk, &mut judge)?;
        }
    }
    flush(&mut chunk, &mut judge)?;
    let n_rows = rows.rows;
    if n_rows == 0 {
        return Err(read::refuse(src.name(), "has no data rows"));
    }
    if n_rows == after_end {
        let (kind, te) = end.clone().unwrap_or_default();
        return Err(read::refuse(
            src.name(),
            format!(
                "has no row before the end of the model (the {kind} at t = {te}): every row, \
                 from row 1, is after it"
            ),
        ));
    }
    let events = events::judge(
        &followed,
        &judge.transitions,
        judge.n_transitions,
        judge.mode_at.is_some(),
        &judge.phases,
        lim.event_tol,
    );
    let mut notes = Vec::new();
    if h.schema1_like
        && judge
            .stats
            .iter()
            .any(|c| c.name == "phi2" && c.failures + c.undecided > 0)
    {
        notes.push(
            "the header is a full column list of the first golden schema (cylroll-golden/1); \
             it is judged as schema 2 (phi2 = 0 at the start), and phi2 fails: a candidate with \
             the first schema's phi2 (the paper's gauge, r1 theta0/r2 below) is judged with \
             --schema 1"
                .to_string(),
        );
    }
    Ok(CheckReport {
        notes,
        case: case.name.clone(),
        rtol: lim.rtol,
        atol: lim.atol,
        event_tol: lim.event_tol,
        rows: n_rows,
        rows_after_end: after_end,
        first_after_end,
        end,
        first_undecided: judge.first_undecided,
        columns: judge.stats,
        first_failure: judge.first,
        digits,
        branch,
        phases: judge.phases,
        events,
    })
}

impl Judge<'_> {
    /// Holds one row against the oracle's, updating the statistics, the
    /// phases and the candidate's transitions.
    fn row(&mut self, row: usize, t: &Exact, vals: &[Cell], orow: &Row) -> Result<()> {
        let p = 128;
        let tag = orow.phase.tag();
        let t_text = t.to_string();
        let t_f = t.to_f64();
        // the reference's phases on the candidate's grid
        if self.phases.last().is_none_or(|ph| ph.tag != tag) {
            self.phases.push(PhaseInfo {
                tag: tag.clone(),
                t_first: t_text.clone(),
                t_last: t_text.clone(),
                t_first_f: t_f,
                t_last_f: t_f,
                row_first: row,
                row_last: row,
                rows: 0,
            });
            for st in &mut self.stats {
                st.phases.push(PhaseColumn {
                    max_abs: 0.0,
                    max_abs_t: "-".into(),
                    failures: 0,
                    worst_ratio: 0.0,
                    undecided: 0,
                });
            }
        }
        let k = self.phases.len() - 1;
        {
            let ph = &mut self.phases[k];
            ph.t_last = t_text.clone();
            ph.t_last_f = t_f;
            ph.row_last = row;
            ph.rows += 1;
        }
        let theta = orow.values[THETA].value.to_f64();
        // the candidate's transitions
        let mode = self.mode_at.map(|m| vals[m].1.clone());
        if let (Some(pr), Some(m)) = (&self.prev, &mode) {
            if let Some(pm) = &pr.mode {
                if pm != m {
                    self.n_transitions += 1;
                    if self.transitions.len() < MAX_TRANSITIONS {
                        self.transitions.push(Transition {
                            from: pm.clone(),
                            to: m.clone(),
                            rows: (pr.row, row),
                            t: (pr.t.clone(), t_text.clone()),
                            t_f: (pr.t_f, t_f),
                            theta: (pr.theta, theta),
                        });
                    }
                }
            }
        }
        self.prev = Some(Prev {
            row,
            t: t_text.clone(),
            t_f,
            mode,
            theta,
        });
        for (j, (gi, text, _)) in vals.iter().enumerate() {
            let st = &mut self.stats[j];
            if *gi == MODE {
                // the phase: the same mode, or flight — or, within event-tol
                // of a change of mode, the mode on either side of it (a row
                // one step late at an event failed while the event passed)
                let m = text.trim();
                let near_change = self.changes.iter().any(|(th, b, a)| {
                    (theta - th).abs() <= self.event_tol
                        && (mode_matches(m, b) || mode_matches(m, a))
                });
                if !mode_matches(m, &tag) && !near_change {
                    st.failures += 1;
                    st.phases[k].failures += 1;
                    st.worst_ratio = f64::INFINITY;
                    st.phases[k].worst_ratio = f64::INFINITY;
                    st.worst_bound = "mode";
                    if st.max_abs_t == "-" {
                        st.max_abs_t = t_text.clone();
                    }
                    if st.phases[k].max_abs_t == "-" {
                        st.phases[k].max_abs_t = t_text.clone();
                    }
                    if self.first.is_none() {
                        self.first = Some(FirstFailure {
                            row,
                            t: t_text.clone(),
                            column: st.name.clone(),
                            candidate: text.clone(),
                            oracle: tag.clone(),
                            limit: 0.0,
                            bound: "mode",
                        });
                    }
                } else if st.worst_bound == "-" {
                    st.worst_bound = "mode";
                }
                continue;
            }
            let tol = self.tols[*gi];
            let o = &orow.values[*gi];
            let mut cand = Exact::parse(&st.name, text, false)?.to_float(p);
            let shifted = crate::motion::COLUMNS[*gi] == "phi2" && !self.phi2_shift.is_zero();
            if shifted {
                cand += &self.phi2_shift;
            }
            // a value printed as 0 is 0 to the verified accuracy: compare
            // with 0 (and no relative error), not with its unverified digits
            let ov = if o.digits == 0 && o.text == "0" {
                Float::new(p)
            } else {
                Float::with_val(p, &o.value)
            };
            let err = Float::with_val(p, &cand - &ov).abs();
            let mag = Float::with_val(p, ov.abs_ref());
            let abs = err.to_f64();
            if abs > st.max_abs || st.max_abs_t == "-" {
                st.max_abs = abs;
                st.max_abs_t = t_text.clone();
            }
            let pc = &mut st.phases[k];
            if abs > pc.max_abs || pc.max_abs_t == "-" {
                pc.max_abs = abs;
                pc.max_abs_t = t_text.clone();
            }
            if !mag.is_zero() {
                let rel = Float::with_val(p, &err / &mag).to_f64();
                if st.max_rel.is_none_or(|m| rel > m) {
                    st.max_rel = Some(rel);
                    st.max_rel_t = t_text.clone();
                }
            }
            let rel_term = Float::with_val(p, &mag * tol.rtol);
            let bound = if rel_term > tol.atol { "rtol" } else { "atol" };
            let limit = rel_term + tol.atol;
            let ratio = if limit.is_zero() {
                if err.is_zero() {
                    0.0
                } else {
                    f64::INFINITY
                }
            } else {
                Float::with_val(p, &err / &limit).to_f64()
            };
            if ratio > st.worst_ratio || st.worst_bound == "-" {
                st.worst_ratio = ratio;
                st.worst_bound = bound;
            }
            if ratio > st.phases[k].worst_ratio {
                st.phases[k].worst_ratio = ratio;
            }
            // the oracle's value is within its error bound of the truth: a
            // verdict is certain only when |err| is farther than that from
            // the limit
            let u = Float::with_val(p, &o.err_bound);
            let certain_fail = Float::with_val(p, &err - &u) > limit;
            let certain_pass = Float::with_val(p, &err + &u) <= limit;
            // a schema-1 φ2 (the paper's gauge) is compared in the
            // reference's: both quoted in it (the file's value beside)
            let failure = || FirstFailure {
                row,
                t: t_text.clone(),
                column: st.name.clone(),
                candidate: if shifted {
                    format!(
                        "{} (schema 1: {text})",
                        crate::numeric::decimal::to_sig(&cand, 17)
                    )
                } else {
                    text.clone()
                },
                oracle: o.text.clone(),
                limit: limit.to_f64(),
                bound,
            };
            if certain_fail {
                if self.first.is_none() {
                    self.first = Some(failure());
                }
                st.failures += 1;
                st.phases[k].failures += 1;
            } else if !certain_pass {
                if self.first_undecided.is_none() {
                    self.first_undecided = Some(failure());
                }
                st.undecided += 1;
                st.phases[k].undecided += 1;
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The oracle's refusal on a chunk of candidate rows names the row whose
    /// time it quotes with its line in the file, and otherwise the chunk's
    /// rows and lines (the README: every refusal names the file, the data
    /// row and its line); rows of an array have no lines.
    #[test]
    fn a_refusal_on_a_chunk_names_the_rows_and_their_lines() {
        let t = |s: &str| Exact::parse("t", s, false).unwrap();
        let chunk: Chunk = vec![
            (read::RowLabel::new(3, Some(5)), t("0.5"), Vec::new()),
            (read::RowLabel::new(4, Some(7)), t("0.75"), Vec::new()),
        ];
        let msg = |e: Error| e.to_string();
        let one = msg(at_rows(Error::invalid("t", "0.75", "x"), "c.csv", &chunk));
        assert!(one.contains("candidate c.csv, row 4 (line 7)"), "{one}");
        let all = msg(at_rows(Error::not_physical("no"), "c.csv", &chunk));
        assert!(all.contains("rows 3-4 (lines 5-7)"), "{all}");
        let arr: Chunk = vec![(read::RowLabel::new(3, None), t("0.5"), Vec::new())];
        let bare = msg(at_rows(Error::invalid("t", "0.5", "x"), "array", &arr));
        assert!(bare.contains("row 3)") && !bare.contains("line"), "{bare}");
    }

    #[test]
    fn the_column_indices_name_their_columns() {
        assert_eq!(crate::motion::COLUMNS[THETA], "theta");
        assert_eq!(crate::motion::COLUMNS[17], "N12");
        assert_eq!(known_columns()[MODE], "mode");
    }

    #[test]
    fn the_finest_rtol_follows_the_digits() {
        assert_eq!(finest_rtol(20), 1e-18);
        assert_eq!(finest_rtol(2), 1.0);
    }
}
