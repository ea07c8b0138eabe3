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
//! - θ* within `event_tol` of the candidate's bracket (its last closed row
//!   and first open one): the `part` branch;
//! - θs within `event_tol` of it: the `stay` branch;
//! - inside the window, away from both ends: `part-at` its own angle, the
//!   closed branch's θ midway in time between the two rows (it parted
//!   lawfully inside the window; its flight is compared with the reference
//!   that parts there);
//! - before θ* (the bracket ends more than `event_tol` before it): not
//!   lawful, a failing verdict; compared with the closed branch;
//! - after θs: not lawful either (the contact cannot stay closed where
//!   N12 = 0); compared with the closed branch.

use super::read::{Rows, Source};
use super::{Limits, MODE};
use crate::error::Result;
use crate::exact::Exact;
use crate::golden::Case;
use crate::motion::{Branch, Kind};
use crate::oracle::{Answer, Options};

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

/// Pass 1: where the candidate parts (None: it never does, or it has no
/// column to tell by).
fn find_parting(src: &dyn Source, case: &Case, lim: &Limits, atol_n12: f64) -> Result<Option<Found>> {
    let mut rows = Rows::open(src, case, lim)?;
    let h = rows.header.clone();
    let mode_at = h.idx.iter().filter(|&&i| i != 0).position(|&i| i == MODE);
    let n12 = crate::motion::COLUMNS.iter().position(|c| *c == "N12").unwrap_or(0);
    let n12_at = h.idx.iter().filter(|&&i| i != 0).position(|&i| i == n12);
    if mode_at.is_none() && n12_at.is_none() {
        return Ok(None);
    }
    let mut prev: Option<(usize, Exact)> = None;
    // N12: the last loaded row and the row after it
    let mut loaded: Option<(usize, Exact)> = None;
    let mut after: Option<(usize, Exact)> = None;
    let mut any_loaded = false;
    while let Some((row, t, cells)) = rows.next_row()? {
        if let Some(k) = mode_at {
            if cells[k].1 == "flight" {
                let (rc, tc) = prev.unwrap_or((row, t.clone()));
                return Ok(Some(Found {
                    row_closed: rc,
                    t_closed: tc,
                    row_open: row,
                    t_open: t,
                    by: "mode",
                }));
            }
        } else if let Some(k) = n12_at {
            if cells[k].2.abs() > atol_n12 {
                loaded = Some((row, t.clone()));
                after = None;
                any_loaded = true;
            } else if after.is_none() && any_loaded {
                after = Some((row, t.clone()));
            }
        }
        prev = Some((row, t));
    }
    if mode_at.is_some() {
        return Ok(None);
    }
    Ok(match (loaded, after) {
        (Some((rc, tc)), Some((ro, to))) => Some(Found {
            row_closed: rc,
            t_closed: tc,
            row_open: ro,
            t_open: to,
            by: "N12",
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
}

/// The branch to follow: the requested one, or under `auto` the one the
/// candidate took (reading it once, `atol_n12` the atol of its N12).
pub fn decide(
    src: &dyn Source,
    case: &Case,
    lim: &Limits,
    stay: &Answer,
    atol_n12: f64,
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
    let Some(f) = find_parting(src, case, lim, atol_n12)? else {
        let h = Rows::open(src, case, lim)?.header;
        let n12 = crate::motion::COLUMNS.iter().position(|c| *c == "N12").unwrap_or(0);
        rep.why = if !h.has(MODE) && !h.has(n12) {
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
    let (thetas, _) = crate::oracle::theta_at_times(
        &case.model,
        &[f.t_closed.clone(), t_mid.clone(), f.t_open.clone()],
        &Options::digits(lim.digits),
    )?;
    let th = |i: usize| (thetas[i].text.clone(), thetas[i].value.to_f64());
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
        short(p.theta_closed.1),
        short(p.theta_open.1)
    );
    let (d_star, d_end) = (dist(star_s), dist(end_s));
    if d_star <= tol || d_end <= tol {
        if d_star <= d_end {
            rep.followed = Branch::Part;
            rep.why = format!(
                "{found}: at the branch point theta* = {star_text} (within event-tol {tol:e}): the \
                 part branch, as velocity-level complementarity solvers take"
            );
        } else {
            rep.why = format!(
                "{found}: at the end of the closed branch theta_s = {end_text} (within event-tol \
                 {tol:e}): the closed branch (stay)"
            );
        }
    } else if a > star_s && a < end_s {
        let at = Exact::parse("part-at", &p.theta_mid.0, false)?;
        rep.why = format!(
            "{found}: inside the window [theta*, theta_s] = [{star_text}, {end_text}] where \
             parting is lawful; compared with the reference that parts midway between those \
             rows, at theta = {at}"
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

/// A short decimal for messages.
pub fn short(x: f64) -> String {
    format!("{x:.9}")
        .trim_end_matches('0')
        .trim_end_matches('.')
        .to_string()
}
