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

pub use branch::{BranchReport, Parting, Request as BranchRequest};
pub use read::{File, Source, Text, MAX_LINE_BYTES};
pub use tol::{parse_override, Override, Tol};

use crate::error::Result;
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

/// The index of `theta` in [`crate::motion::COLUMNS`].
const THETA: usize = 1;

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
/// followed (its first impact or a lift-off).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum PastEnd {
    /// Refuse the candidate (bad input).
    #[default]
    Refuse,
    /// Leave them out and count them (`rows_after_end`).
    Drop,
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
    /// The tolerance applied (None for `mode`).
    pub tol: Option<Tol>,
    /// Per phase of [`CheckReport::phases`], in order.
    pub phases: Vec<PhaseColumn>,
}

/// The first value out of tolerance.
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
    /// `slip_onset`, `separation`, …; `none` for a transition of the
    /// candidate the reference does not have.
    pub kind: String,
    /// `floor` or `contact`, where the event concerns one.
    pub contact: Option<String>,
    /// The mode entered (`flight`, `stick/slip+`; `-` at the end of the model).
    pub mode: String,
    /// The reference's time and θ (verified digits; None for `none`).
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
    /// Rows left out after the end of the model ([`PastEnd::Drop`]).
    pub rows_after_end: usize,
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
}

impl CheckReport {
    /// Whether every value is within tolerance, every judged event within
    /// `event_tol` and the branch lawful.
    pub fn passed(&self) -> bool {
        self.first_failure.is_none()
            && self.branch.lawful
            && self.events.list.iter().all(|e| e.passed != Some(false))
    }

    /// Whether phase `k` passes (every column within tolerance there).
    pub fn phase_passed(&self, k: usize) -> bool {
        self.columns
            .iter()
            .all(|c| c.phases.get(k).is_none_or(|p| p.failures == 0))
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
    phases: Vec<PhaseInfo>,
    transitions: Vec<Transition>,
    n_transitions: usize,
    prev: Option<Prev>,
    mode_at: Option<usize>,
}

/// Checks the candidate `src` against `case` with the tolerances and limits
/// `lim`: under [`BranchRequest::Auto`] where the motion is not unique the
/// candidate is read twice (first to find where it parted), else once; the
/// oracle is evaluated in chunks of [`CHUNK_ROWS`] rows, so memory does not
/// grow with the number of rows.
///
/// Errors: a malformed candidate (header, fields, numbers), more rows than
/// `lim.max_rows`, a tolerance that is not finite and >= 0 or names a
/// column the candidate lacks, nothing to compare, times the oracle refuses
/// (after the end of the model, unless [`PastEnd::Drop`]).
pub fn check_source(src: &dyn Source, case: &Case, lim: &Limits) -> Result<CheckReport> {
    let digits = lim.digits;
    let tols = tol::tolerances(&case.model, lim.rtol, lim.atol, &lim.tols)?;
    if !lim.event_tol.is_finite() || lim.event_tol < 0.0 {
        return Err(crate::error::Error::invalid(
            "event-tol",
            lim.event_tol,
            "must be a finite number >= 0 (radians of theta)",
        ));
    }
    // the header first: a malformed candidate is refused before any oracle work
    let header = Rows::open(src, case, lim)?.header;
    for o in &lim.tols {
        let gi = crate::motion::COLUMNS.iter().position(|c| *c == o.column);
        if !gi.is_some_and(|g| header.has(g)) {
            return Err(crate::error::Error::invalid(
                "tol",
                format!("{}={}", o.column, o.rtol),
                format!(
                    "names a column the candidate does not have (its columns: {})",
                    header.cols.join(", ")
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
    let n12 = crate::motion::COLUMNS
        .iter()
        .position(|c| *c == "N12")
        .unwrap_or(0);
    let branch = branch::decide(src, case, lim, &stay, tols[n12].atol)?;
    let followed = if branch.followed == Branch::Stay {
        stay
    } else {
        crate::oracle::separation(&case.model, &opts(branch.followed.clone()))?
    };
    let t_end = followed
        .events
        .iter()
        .find(|e| e.phase.is_none())
        .map(|e| e.t.value.clone());

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
                tol: (gi != MODE).then(|| tols[gi]),
                phases: Vec::new(),
            })
            .collect(),
        first: None,
        phases: Vec::new(),
        transitions: Vec::new(),
        n_transitions: 0,
        prev: None,
        mode_at: h.idx.iter().filter(|&&i| i != 0).position(|&i| i == MODE),
    };
    let mut dropped = 0usize;
    let mut chunk: Vec<(usize, Exact, Vec<Cell>)> = Vec::with_capacity(CHUNK_ROWS);
    let trajectory_opts = opts(branch.followed.clone());
    let flush = |chunk: &mut Vec<(usize, Exact, Vec<Cell>)>, judge: &mut Judge| -> Result<()> {
        if chunk.is_empty() {
            return Ok(());
        }
        let times: Vec<Exact> = chunk.iter().map(|d| d.1.clone()).collect();
        let orows = crate::oracle::trajectory(&case.model, &times, &trajectory_opts)?.rows;
        for ((row, t, vals), orow) in chunk.iter().zip(&orows) {
            judge.row(*row, t, vals, orow)?;
        }
        chunk.clear();
        Ok(())
    };
    while let Some((row, t, cells)) = rows.next_row()? {
        if lim.past_end == PastEnd::Drop {
            if let Some(te) = &t_end {
                // a margin of 1e-12 (relative) keeps the row at the impact itself out
                let tf = t.to_float(te.prec());
                let margin = Float::with_val(te.prec(), te.abs_ref()) * 1e-12f64;
                if tf >= Float::with_val(te.prec(), te - &margin) {
                    dropped += 1;
                    continue;
                }
            }
        }
        chunk.push((row, t, cells));
        if chunk.len() == CHUNK_ROWS {
            flush(&mut chunk, &mut judge)?;
        }
    }
    flush(&mut chunk, &mut judge)?;
    let n_rows = rows.rows;
    if n_rows == 0 {
        return Err(crate::error::Error::invalid(
            "candidate",
            src.name(),
            "has no data rows",
        ));
    }
    if n_rows == dropped {
        return Err(crate::error::Error::invalid(
            "candidate",
            src.name(),
            "has no rows before the end of the model (every row was after it)",
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
    Ok(CheckReport {
        case: case.name.clone(),
        rtol: lim.rtol,
        atol: lim.atol,
        event_tol: lim.event_tol,
        rows: n_rows,
        rows_after_end: dropped,
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
                // the phase: the same mode, or flight
                if text.trim() != tag {
                    st.failures += 1;
                    st.phases[k].failures += 1;
                    st.worst_ratio = f64::INFINITY;
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
            let mut cand = Exact::parse("value", text, false)?.to_float(p);
            if crate::motion::COLUMNS[*gi] == "phi2" {
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
            if err > limit {
                st.failures += 1;
                st.phases[k].failures += 1;
                if self.first.is_none() {
                    self.first = Some(FirstFailure {
                        row,
                        t: t_text.clone(),
                        column: st.name.clone(),
                        candidate: text.clone(),
                        oracle: o.text.clone(),
                        limit: limit.to_f64(),
                        bound,
                    });
                }
            }
        }
        Ok(())
    }
}
