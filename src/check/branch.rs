//! Which continuation a candidate is judged against where the rigid-body
//! motion is not unique.
//!
//! From the branch point θ* (the event `indeterminate`) to the end of the
//! closed branch θs (its `separation`) the cylinders may lawfully part at
//! any instant. `auto` finds where the candidate parted (its first row of
//! mode `flight`; without a `mode` column the row from which its `N12` stays
//! 0 within its atol to the end), which brackets its parting between its
//! last closed row and its first open one, and classifies by the closed
//! branch's θ over that bracket:
//!
//! - θ* within `event_tol` of the bracket: the `part` branch; θs within it:
//!   the `stay` branch; both (a coarse grid): the branch — `stay`, `part`, or
//!   parting inside the window at the angle that fits best — whose flight is
//!   nearest the candidate's rows from its parting on (the sum over its
//!   numeric cells of |candidate − reference| / the column's scale);
//! - inside the window, away from both ends: `part-at` the angle in the
//!   bracket whose flight is nearest those rows (a golden-section search;
//!   the bracket's middle in time without a numeric column);
//! - before θ* (the bracket ends more than `event_tol` before it): not
//!   lawful, a failing verdict; compared with the closed branch;
//! - after θs: not lawful either (the contact cannot stay closed where
//!   N12 = 0); compared with the closed branch.

use super::read::{Cell, Rows, Source};
use super::tol::Tol;
use super::{Limits, MODE};
use crate::error::Result;
use crate::exact::Exact;
use crate::golden::Case;
use crate::motion::{Branch, Kind};
use crate::oracle::{Answer, Options};

/// The index of `N12` in [`crate::motion::COLUMNS`].
const N12: usize = 17;

/// The branch a check is asked to follow.
#[derive(Debug, Clone, PartialEq, Default)]
pub enum Request {
    /// The branch the candidate took (see the module's documentation).
    #[default]
    Auto,
    /// The closed branch: the contact persists while it can.
    Stay,
    /// Part at the branch point θ*.
    Part,
    /// Part where θ reaches the angle (inside the window).
    PartAt(Exact),
}

impl Request {
    /// `auto`, `stay`, `part`, `part-at θ`.
    pub fn name(&self) -> String {
        match self {
            Request::Auto => "auto".into(),
            Request::Stay => "stay".into(),
            Request::Part => "part".into(),
            Request::PartAt(a) => format!("part-at {a}"),
        }
    }
}

/// Where the candidate parted: its last closed row and its first open one.
#[derive(Debug, Clone)]
pub struct Parting {
    /// 1-based row of the last closed row (= `row_open` when the candidate
    /// is open from its first row).
    pub row_closed: usize,
    /// 1-based row of the first open row.
    pub row_open: usize,
    /// Their times.
    pub t_closed: Exact,
    /// Time of the first open row.
    pub t_open: Exact,
    /// How it was found: `mode` (the first row of mode `flight`) or `N12`
    /// (N12 within its atol of 0 from this row to the end).
    pub by: &'static str,
    /// The closed branch's θ at the last closed row (verified text; f64).
    pub theta_closed: (String, f64),
    /// Its θ midway in time between the two rows: where the candidate is
    /// taken to part on the `part-at` branch.
    pub theta_mid: (String, f64),
    /// θ of the closed branch at the first open row.
    pub theta_open: (String, f64),
}

/// The branch followed and why.
#[derive(Debug, Clone)]
pub struct BranchReport {
    /// What was asked (`auto`, `stay`, `part`, `part-at θ`).
    pub requested: String,
    /// The branch followed.
    pub followed: Branch,
    /// Why, in words.
    pub why: String,
    /// [θ*, θs] (verified texts and f64) where parting is lawful; None
    /// where the motion is unique.
    pub window: Option<[(String, f64); 2]>,
    /// The candidate's parting, when `auto` looked for it and found it.
    pub parting: Option<Parting>,
    /// Whether the candidate's branch is lawful (false: it parted before
    /// θ* or after θs).
    pub lawful: bool,
}

/// The window [θ*, θs] of the closed branch's answer, if the motion is not
/// unique there.
pub fn window(stay: &Answer) -> Option<[(String, f64); 2]> {
    let star = stay.event(Kind::Indeterminate)?;
    let end = stay
        .events
        .iter()
        .find(|e| e.kind == Kind::Separation && e.t.value > star.t.value)?;
    Some([
        (star.theta.text.clone(), star.theta.value.to_f64()),
        (end.theta.text.clone(), end.theta.value.to_f64()),
    ])
}

/// Rows of the candidate kept from its first open row on, to tell the
/// branches apart where its bracket holds both ends of the window.
const ROWS_AFTER: usize = 8;

/// A candidate row: its number, time and cells.
type CandRow = (usize, Exact, Vec<Cell>);

/// Pass 1: where the candidate parts (None: it never does, or it has no
/// column to tell by).
fn find_parting(
    src: &dyn Source,
    case: &Case,
    lim: &Limits,
    atol_n12: f64,
) -> Result<Option<Found>> {
    let mut rows = Rows::open(src, case, lim)?;
    let h = rows.header.clone();
    let mode_at = h.idx.iter().filter(|&&i| i != 0).position(|&i| i == MODE);
    let n12_at = h.idx.iter().filter(|&&i| i != 0).position(|&i| i == N12);
    if mode_at.is_none() && n12_at.is_none() {
        return Ok(None);
    }
    let mut prev: Option<(usize, Exact)> = None;
    // the last closed row and the first open one after it; the rows from there
    let mut closed: Option<(usize, Exact)> = None;
    let mut open: Option<(usize, Exact)> = None;
    let mut after: Vec<CandRow> = Vec::new();
    let mut found_by_mode = false;
    while let Some((row, t, cells)) = rows.next_row()? {
        if let Some(k) = mode_at {
            if found_by_mode {
                after.push((row, t, cells));
                if after.len() == ROWS_AFTER {
                    break;
                }
                continue;
            }
            if cells[k].1 == "flight" {
                // the first row of mode flight (open from the first row: both ends are it)
                closed = Some(prev.clone().unwrap_or((row, t.clone())));
                open = Some((row, t.clone()));
                after.push((row, t, cells));
                found_by_mode = true;
                continue;
            }
        } else if let Some(k) = n12_at {
            // the row from which N12 stays within its atol of 0 to the last row
            if cells[k].2.abs() > atol_n12 {
                closed = Some((row, t.clone()));
                open = None;
                after.clear();
            } else if closed.is_some() {
                if open.is_none() {
                    open = Some((row, t.clone()));
                }
                if after.len() < ROWS_AFTER {
                    after.push((row, t.clone(), cells));
                }
            }
        }
        prev = Some((row, t));
    }
    if mode_at.is_some() && !found_by_mode {
        return Ok(None);
    }
    Ok(match (closed, open) {
        (Some((rc, tc)), Some((ro, to))) => Some(Found {
            row_closed: rc,
            t_closed: tc,
            row_open: ro,
            t_open: to,
            by: if mode_at.is_some() { "mode" } else { "N12" },
            after,
        }),
        _ => None,
    })
}

struct Found {
    row_closed: usize,
    t_closed: Exact,
    row_open: usize,
    t_open: Exact,
    by: &'static str,
    after: Vec<CandRow>,
}

/// How far the candidate's rows are from the reference on `branch`: the sum
/// over its numeric cells of |candidate − oracle| / the column's scale
/// (None: the reference cannot be evaluated there, or no cell to compare).
fn distance(
    case: &Case,
    branch: Branch,
    rows: &[CandRow],
    tols: &[Tol],
    shift: f64,
) -> Option<f64> {
    let r = residuals(case, branch, rows, tols, shift)?;
    Some(r.iter().map(|x| x.abs()).sum())
}

/// The candidate's numeric cells against the reference on `branch`, each
/// (candidate − oracle) / the column's scale (None: the reference cannot be
/// evaluated there, or no cell to compare).
fn residuals(
    case: &Case,
    branch: Branch,
    rows: &[CandRow],
    tols: &[Tol],
    shift: f64,
) -> Option<Vec<f64>> {
    if rows.is_empty() {
        return None;
    }
    let times: Vec<Exact> = rows.iter().map(|r| r.1.clone()).collect();
    let opts = Options {
        digits: 17,
        branch,
        method: crate::motion::Method::Auto,
    };
    let ans = crate::oracle::trajectory(&case.model, &times, &opts).ok()?;
    debug_assert_eq!(ans.rows.len(), rows.len());
    let mut out = Vec::new();
    for ((_, _, cells), orow) in rows.iter().zip(&ans.rows) {
        for (gi, _, v) in cells {
            if *gi == MODE {
                continue;
            }
            let v = if crate::motion::COLUMNS[*gi] == "phi2" {
                v + shift
            } else {
                *v
            };
            out.push((v - orow.values[*gi].value.to_f64()) / tols[*gi].scale);
        }
    }
    (!out.is_empty()).then_some(out)
}

/// The branch to follow: the requested one, or under `auto` the one the
/// candidate took (reading it once; `tols` the columns' tolerances).
pub fn decide(
    src: &dyn Source,
    case: &Case,
    lim: &Limits,
    stay: &Answer,
    tols: &[Tol],
) -> Result<BranchReport> {
    let win = window(stay);
    let requested = lim.branch.name();
    let mut rep = BranchReport {
        requested,
        followed: Branch::Stay,
        why: String::new(),
        window: win.clone(),
        parting: None,
        lawful: true,
    };
    let unique = "the motion is unique (no branch point): the one motion";
    match &lim.branch {
        Request::Stay | Request::Part | Request::PartAt(_) if win.is_none() => {
            rep.followed = match &lim.branch {
                Request::Part => Branch::Part,
                Request::PartAt(a) => Branch::PartAt(a.clone()),
                _ => Branch::Stay,
            };
            rep.why = format!("requested; {unique}");
            return Ok(rep);
        }
        Request::Stay => {
            rep.why = "requested: the closed branch (the contact persists while it can)".into();
            return Ok(rep);
        }
        Request::Part => {
            rep.followed = Branch::Part;
            rep.why = "requested: the cylinders part at the branch point theta*".into();
            return Ok(rep);
        }
        Request::PartAt(a) => {
            rep.followed = Branch::PartAt(a.clone());
            rep.why = format!("requested: the cylinders part where theta reaches {a}");
            return Ok(rep);
        }
        Request::Auto => {}
    }
    let Some([(star_text, star), (end_text, end)]) = win else {
        rep.why = unique.into();
        return Ok(rep);
    };
    let Some(f) = find_parting(src, case, lim, tols[N12].atol)? else {
        let h = Rows::open(src, case, lim)?.header;
        if !h.has(MODE) && !h.has(N12) {
            if let Some((b, why)) = nearest_branch(src, case, lim, stay, tols, (star, end))? {
                rep.followed = b;
                rep.why = why;
                return Ok(rep);
            }
        }
        rep.why = if !h.has(MODE) && !h.has(N12) {
            "without a mode or N12 column the candidate's parting cannot be found: the closed \
             branch (stay)"
                .into()
        } else if h.has(MODE) {
            "the candidate does not part (no row of mode flight): the closed branch (stay)".into()
        } else {
            "the candidate does not part (its N12 does not stay 0 to its last row): the closed \
             branch (stay)"
                .into()
        };
        return Ok(rep);
    };
    let t_mid = Exact::rational(
        rug::Rational::from(&f.t_closed.coef + &f.t_open.coef) / rug::Rational::from(2),
    );
    // the closed branch's θ at the bracket (a time after the end of its
    // motion, the first impact, is taken at that end)
    let t_stay_end = stay
        .events
        .iter()
        .find(|e| e.phase.is_none())
        .and_then(|e| e.t.value.to_rational());
    let clamp = |t: &Exact| match &t_stay_end {
        Some(te) if t.coef > *te => Exact::rational(te.clone()),
        _ => t.clone(),
    };
    let (thetas, _) = crate::oracle::theta_at_times(
        &case.model,
        &[clamp(&f.t_closed), clamp(&t_mid), clamp(&f.t_open)],
        &Options::digits(lim.digits),
    )?;
    let th = |i: usize| (thetas[i].text.clone(), thetas[i].value.to_f64());
    // for the message: at most 10 significant digits, never more than verified
    let quote = |i: usize| {
        let v = &thetas[i];
        if v.digits > 10 {
            crate::numeric::decimal::to_sig(&v.value, 10)
        } else {
            v.text.clone()
        }
    };
    let p = Parting {
        row_closed: f.row_closed,
        row_open: f.row_open,
        t_closed: f.t_closed,
        t_open: f.t_open,
        by: f.by,
        theta_closed: th(0),
        theta_mid: th(1),
        theta_open: th(2),
    };
    // in the direction of the motion
    let s = if end < 0.0 { -1.0 } else { 1.0 };
    let (a, b) = (s * p.theta_closed.1, s * p.theta_open.1);
    let (star_s, end_s) = (s * star, s * end);
    let dist = |x: f64| {
        if x < a {
            a - x
        } else if x > b {
            x - b
        } else {
            0.0
        }
    };
    let tol = lim.event_tol;
    let found = format!(
        "the candidate parts between rows {} and {} (t = {} .. {}, found by its {} column; the \
         closed branch's theta there {} .. {})",
        p.row_closed,
        p.row_open,
        p.t_closed,
        p.t_open,
        p.by,
        quote(0),
        quote(2)
    );
    let (d_star, d_end) = (dist(star_s), dist(end_s));
    let mid_inside = s * p.theta_mid.1 > star_s && s * p.theta_mid.1 < end_s;
    if d_star <= tol || d_end <= tol {
        // the bracket holds an end of the window (or both): the parting may
        // be at that end or anywhere in the bracket inside the window, and
        // the rows after it decide (a coarse grid whose bracket holds θ* or
        // θs alone was taken for that end's branch unseen: a lawful parting
        // inside the window was then judged against the wrong branch, the
        // verdict depending on the grid)
        let shift = Rows::open(src, case, lim)?.header.phi2_shift.to_f64();
        let mut options = Vec::new();
        if d_end <= tol {
            options.push((Branch::Stay, "stay"));
        }
        if d_star <= tol {
            options.push((Branch::Part, "part"));
        }
        // parting inside the window: at the angle in the bracket that fits
        // its rows best
        let range = (a.max(star_s), b.min(end_s));
        let fit = fit_part_at(case, range, s, &f.after, tols, shift);
        if let Some((theta, _, _)) = fit {
            // scored with the ends' branches even within event-tol of one
            // (it was dropped there: a parting at 1.047, 1.0003e-3 before θs,
            // followed stay once the refined fit came within 1e-3 of θs,
            // and failed); the same angle as an end is that end
            let at_end =
                (d_star <= tol && s * theta == star_s) || (d_end <= tol && s * theta == end_s);
            if !at_end {
                // the fitted binary64 angle, quoted exactly
                let at =
                    Exact::rational(Exact::parse("part-at", &format!("{theta:e}"), false)?.coef);
                options.push((Branch::PartAt(at), "part-at"));
            }
        } else if mid_inside && d_star <= tol && d_end <= tol {
            let at = Exact::parse("part-at", &p.theta_mid.0, false)?;
            options.push((Branch::PartAt(at), "part-at"));
        }
        let options = options
            .into_iter()
            .map(|(b, name)| {
                let name = match &b {
                    Branch::PartAt(at) => format!("{name} {at}"),
                    _ => name.to_string(),
                };
                (b, name)
            })
            .collect();
        let sc = score_options(case, options, f.after.clone(), tols, shift)?;
        let best = sc.best.map(|i| (&sc.list[i].0, sc.list[i].1.as_str()));
        let listed = sc.listed();
        let holds = match (d_star <= tol, d_end <= tol) {
            (true, true) => format!("both theta* = {star_text} and theta_s = {end_text}"),
            (true, false) => format!("the branch point theta* = {star_text}"),
            _ => format!("the end of the closed branch theta_s = {end_text}"),
        };
        match best {
            Some((b, name)) => {
                rep.followed = b.clone();
                rep.why = format!(
                    "{found}: the bracket holds {holds} (within event-tol {tol:e}); the \
                     candidate's {} rows from its parting on are nearest the {name} branch \
                     (sum of |candidate - reference| / the column's scale: {listed})",
                    sc.rows,
                );
            }
            None => {
                // nothing after the parting to tell them apart: the end's
                // branch (the closed one where the bracket holds both)
                let (b, name) = if d_end <= tol {
                    (Branch::Stay, "the closed branch (stay)")
                } else {
                    (
                        Branch::Part,
                        "the part branch, as velocity-level complementarity solvers take",
                    )
                };
                rep.followed = b;
                rep.why = format!(
                    "{found}: the bracket holds {holds} (within event-tol {tol:e}) and the \
                     candidate has no numeric column after it to tell the branches apart: {name}"
                );
            }
        }
    } else if a > star_s && a < end_s {
        // where in its bracket it parted: the angle whose lawful flight is
        // nearest its rows after the parting (else the bracket's middle)
        let shift = Rows::open(src, case, lim)?.header.phi2_shift.to_f64();
        let range = (a.max(star_s), b.min(end_s));
        let fit = fit_part_at(case, range, s, &f.after, tols, shift);
        let (at, how) = match fit {
            // the reference parts at the fitted binary64 angle (golden
            // section, then Gauss-Newton steps on the residuals), quoted
            // exactly
            Some((theta, d, n)) => (
                Exact::rational(Exact::parse("part-at", &format!("{theta:e}"), false)?.coef),
                format!(
                    "at the angle in its bracket whose flight is nearest its {n} rows from the \
                     parting on (sum of |candidate - reference| / the column's scale {d:.3e})"
                ),
            ),
            None => (
                Exact::parse("part-at", &p.theta_mid.0, false)?,
                "midway between those rows (no numeric column after the parting to place it by)"
                    .to_string(),
            ),
        };
        rep.why = format!(
            "{found}: inside the window [theta*, theta_s] = [{star_text}, {end_text}] where \
             parting is lawful; compared with the reference that parts {how}: theta = {at}"
        );
        rep.followed = Branch::PartAt(at);
    } else if b < star_s {
        rep.lawful = false;
        rep.why = format!(
            "{found}: before the branch point theta* = {star_text} (by more than event-tol \
             {tol:e}), where the rigid-body motion may not part: not lawful; compared with the \
             closed branch"
        );
    } else {
        rep.lawful = false;
        rep.why = format!(
            "{found}: after the end of the closed branch theta_s = {end_text} (by more than \
             event-tol {tol:e}), where the contact cannot stay closed (N12 = 0 there): not \
             lawful; compared with the closed branch"
        );
    }
    rep.parting = Some(p);
    Ok(rep)
}

/// Branches scored on a candidate's rows: each with its distance
/// ([`distance`]; None where it cannot be evaluated), the best, and the
/// rows used.
struct Scored {
    list: Vec<(Branch, String, Option<f64>)>,
    best: Option<usize>,
    rows: usize,
}

impl Scored {
    /// `name distance, …` for the messages.
    fn listed(&self) -> String {
        self.list
            .iter()
            .map(|(_, name, d)| match d {
                Some(d) => format!("{name} {d:.3e}"),
                None => format!("{name} -"),
            })
            .collect::<Vec<_>>()
            .join(", ")
    }
}

/// `options` scored on `rows`, each branch on the rows before the end of
/// its motion (its first impact) and all on the rows before every end. The
/// best is the nearest, but an end's branch (stay, part) that fits within
/// 25% of a fitted parting is that end's: the noise of the candidate's
/// rows, not its parting.
fn score_options(
    case: &Case,
    options: Vec<(Branch, String)>,
    mut rows: Vec<CandRow>,
    tols: &[Tol],
    shift: f64,
) -> Result<Scored> {
    for (b, _) in &options {
        let ans = crate::oracle::separation(
            &case.model,
            &Options {
                digits: 17,
                branch: b.clone(),
                method: crate::motion::Method::Auto,
            },
        )?;
        if let Some(te) = ans.events.iter().find(|e| e.phase.is_none()) {
            let te = te.t.value.to_f64() * (1.0 - 1e-12);
            rows.retain(|r| r.1.to_f64() < te);
        }
    }
    let list: Vec<(Branch, String, Option<f64>)> = options
        .into_iter()
        .map(|(b, name)| {
            let d = distance(case, b.clone(), &rows, tols, shift);
            (b, name, d)
        })
        .collect();
    let nearest = |fitted: bool, limit: f64| {
        list.iter()
            .enumerate()
            .filter(|(_, (b, _, _))| fitted || !matches!(b, Branch::PartAt(_)))
            .filter_map(|(i, (_, _, d))| d.map(|d| (i, d)))
            .filter(|x| x.1 <= limit)
            .min_by(|x, y| x.1.total_cmp(&y.1))
    };
    // (25%: the fitted angle, a free parameter, absorbs part of the rows'
    // noise — a stay table with 1e-6 noise fitted a parting 8.7e-7 before θs
    // 2.3% nearer, one parting at θ* 9% nearer — while the genuine partings
    // measured inside the window, 5e-4 after θ* or 1e-3 before θs, fit 3.8
    // to 145 times nearer than the end's branch)
    let best = match nearest(true, f64::INFINITY) {
        Some((i, d)) if matches!(list[i].0, Branch::PartAt(_)) => {
            nearest(false, d * 1.25).or(Some((i, d)))
        }
        other => other,
    };
    Ok(Scored {
        best: best.map(|x| x.0),
        rows: rows.len(),
        list,
    })
}

/// Rows of the candidate scored without a mode or N12 column: at most this
/// many from the branch point on, evenly thinned.
const ROWS_SCORED: usize = 32;

/// Without a `mode` or `N12` column the candidate's parting cannot be read
/// from its rows: the branch followed is the one — `stay`, `part`, or
/// parting inside the window at the angle that fits best — whose motion is
/// nearest its numeric cells from the branch point θ* on (None: no row
/// there, or no numeric cell). `window` is (θ*, θs) of the closed branch.
/// (Such a candidate was judged against the closed branch: a PyBullet run,
/// which parts at θ*, given as t, θ and x2 failed after its parting.)
fn nearest_branch(
    src: &dyn Source,
    case: &Case,
    lim: &Limits,
    stay: &Answer,
    tols: &[Tol],
    window: (f64, f64),
) -> Result<Option<(Branch, String)>> {
    let Some(t_star) = stay.event(Kind::Indeterminate).map(|e| e.t.value.to_f64()) else {
        return Ok(None);
    };
    // the rows from θ* on, thinned to at most 2·ROWS_SCORED as they come
    let mut rows = Rows::open(src, case, lim)?;
    let shift = rows.header.phi2_shift.to_f64();
    let (mut kept, mut stride, mut seen) = (Vec::<CandRow>::new(), 1usize, 0usize);
    while let Some((row, t, cells)) = rows.next_row()? {
        if t.to_f64() < t_star {
            continue;
        }
        if seen % stride == 0 {
            kept.push((row, t, cells));
            if kept.len() == 2 * ROWS_SCORED {
                kept = kept.into_iter().step_by(2).collect();
                stride *= 2;
            }
        }
        seen += 1;
    }
    if kept.iter().all(|r| r.2.iter().all(|c| c.0 == MODE)) {
        return Ok(None);
    }
    let (star, end) = window;
    let s = if end < 0.0 { -1.0 } else { 1.0 };
    let mut options = vec![
        (Branch::Stay, "stay".to_string()),
        (Branch::Part, "part".into()),
    ];
    if let Some((theta, _, _)) = fit_part_at(case, (s * star, s * end), s, &kept, tols, shift) {
        let at = Exact::rational(Exact::parse("part-at", &format!("{theta:e}"), false)?.coef);
        options.push((Branch::PartAt(at.clone()), format!("part-at {at}")));
    }
    let sc = score_options(case, options, kept, tols, shift)?;
    let Some(i) = sc.best else {
        return Ok(None);
    };
    let (b, name) = (&sc.list[i].0, &sc.list[i].1);
    let listed = sc.listed();
    Ok(Some((
        b.clone(),
        format!(
            "without a mode or N12 column the candidate's parting is not read from its rows: \
             its {} rows from the branch point theta* on are nearest the {name} branch (sum of \
             |candidate - reference| / the column's scale: {listed})",
            sc.rows,
        ),
    )))
}

/// The parting angle in `range` (in the direction `s` of the motion:
/// s·θ) whose lawful flight is nearest the candidate's `rows` from its
/// parting on, by golden-section search: (θ, its distance, rows used).
fn fit_part_at(
    case: &Case,
    range: (f64, f64),
    s: f64,
    rows: &[CandRow],
    tols: &[Tol],
    shift: f64,
) -> Option<(f64, f64, usize)> {
    // inside the window by a hair: an end rounded to f64 may fall outside it
    let eps = (range.1 - range.0) * 1e-9;
    let range = (range.0 + eps, range.1 - eps);
    if range.1 <= range.0 {
        return None;
    }
    // the rows before the end of the motion parting at either end of the range
    let mut rows = rows.to_vec();
    for x in [range.0, range.1] {
        let at = Exact::parse("part-at", &format!("{:e}", s * x), false).ok()?;
        let opts = Options {
            digits: 17,
            branch: Branch::PartAt(at),
            method: crate::motion::Method::Auto,
        };
        let ans = crate::oracle::separation(&case.model, &opts).ok()?;
        if let Some(te) = ans.events.iter().find(|e| e.phase.is_none()) {
            let te = te.t.value.to_f64() * (1.0 - 1e-6);
            rows.retain(|r| r.1.to_f64() < te);
        }
    }
    let cost = |x: f64| {
        let at = Exact::parse("part-at", &format!("{:e}", s * x), false).ok()?;
        distance(case, Branch::PartAt(at), &rows, tols, shift)
    };
    let g = 0.5 * (5f64.sqrt() - 1.0);
    let (mut lo, mut hi) = range;
    let mut x1 = hi - g * (hi - lo);
    let mut x2 = lo + g * (hi - lo);
    let (mut f1, mut f2) = (cost(x1)?, cost(x2)?);
    // to about 1e-9 of the bracket
    for _ in 0..44 {
        if f1 <= f2 {
            hi = x2;
            x2 = x1;
            f2 = f1;
            x1 = hi - g * (hi - lo);
            f1 = cost(x1).unwrap_or(f64::INFINITY);
        } else {
            lo = x1;
            x1 = x2;
            f1 = f2;
            x2 = lo + g * (hi - lo);
            f2 = cost(x2).unwrap_or(f64::INFINITY);
        }
    }
    let (mut x, mut d) = if f1 <= f2 { (x1, f1) } else { (x2, f2) };
    if !d.is_finite() {
        return None;
    }
    // Gauss-Newton steps on the residuals, linear in the angle near the
    // fit: the golden section alone left about 1e-9 of the bracket, and an
    // exact candidate parting at 1.0123456789012345 failed rtol 1e-10 on
    // its velocities against the angle rounded to 10 digits
    let at = |x: f64| Exact::parse("part-at", &format!("{:e}", s * x), false).ok();
    for _ in 0..3 {
        let h = (hi - lo).max(x.abs() * 1e-12);
        let (Some(a0), Some(a1)) = (at(x), at(x + h)) else {
            break;
        };
        let (Some(r0), Some(r1)) = (
            residuals(case, Branch::PartAt(a0), &rows, tols, shift),
            residuals(case, Branch::PartAt(a1), &rows, tols, shift),
        ) else {
            break;
        };
        let (mut num, mut den) = (0.0, 0.0);
        for (a, b) in r0.iter().zip(&r1) {
            let g = (b - a) / h;
            num += a * g;
            den += g * g;
        }
        if den.is_nan() || den <= 0.0 {
            break;
        }
        let xn = x - num / den;
        if !(xn > range.0 && xn < range.1) {
            break;
        }
        match cost(xn) {
            Some(dn) if dn < d => (x, d) = (xn, dn),
            _ => break,
        }
    }
    // the fit's resolution: the angle's standard error from the residuals
    // left and their slope; the angle is quoted with the fewest digits
    // within half of it (a 12-digit candidate parting at 1 fits 1 + 3e-13:
    // quoted 1; an exact one keeps binary64's digits)
    let h = (hi - lo).max(x.abs() * 1e-12);
    if let (Some(a0), Some(a1)) = (at(x), at(x + h)) {
        if let (Some(r0), Some(r1)) = (
            residuals(case, Branch::PartAt(a0), &rows, tols, shift),
            residuals(case, Branch::PartAt(a1), &rows, tols, shift),
        ) {
            let n = r0.len().max(2) as f64;
            let ss: f64 = r0.iter().map(|r| r * r).sum();
            let gg: f64 = r0.iter().zip(&r1).map(|(a, b)| ((b - a) / h).powi(2)).sum();
            let sigma = (ss / (n - 1.0) / gg).sqrt();
            if sigma.is_finite() && sigma > 0.0 {
                for k in 1..17 {
                    let xr: f64 = format!("{:.*e}", k - 1, x).parse().unwrap_or(x);
                    if (xr - x).abs() > 0.5 * sigma {
                        continue;
                    }
                    // inside the range fitted (so inside the window and the
                    // candidate's bracket), and fitting as well to 0.1%: a
                    // fit a hair inside θs rounded past it and the check was
                    // refused ("invalid part-at"), another rounded out of
                    // its bracket and failed
                    if xr > range.0 && xr < range.1 && cost(xr).is_some_and(|c| c <= d * 1.001) {
                        x = xr;
                    }
                    break;
                }
            }
        }
    }
    Some((s * x, d, rows.len()))
}
