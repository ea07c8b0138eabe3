//! `trajectory`: every column (or those asked) at given times, through
//! every phase, verified on the precision ladder; long tables in blocks of
//! rows so that memory stays bounded ([`trajectory_in_blocks`]); θ alone at
//! times ([`theta_at_times`]).

use super::ladder::{self, event_estimates, events_of, laddered, laddered_short};
use super::{
    branch_notes, check_digits, check_part_at, check_times, check_times_rounded, empty_answer,
    energy_drift, energy_note, infinite, runs, Answer, Options, Question, Row,
};
use crate::error::{Error, Result};
use crate::exact::Exact;
use crate::model::Model;
use crate::motion::{self, Phase, Until};
use crate::numeric::verify::{estimate_rows, precisions, Estimate, RowIter, Run, Verified};
use rug::Float;

/// The first of `times` that [`trajectory`] refuses on its own (a time past
/// the end of the motion), found by bisection on single times (the refused
/// ones are those past the end: a tail of the ascending times), with its
/// error.
fn first_refused_time(
    model: &Model,
    times: &[Exact],
    opts: &Options,
    columns: &[String],
) -> Option<Error> {
    let refused = |i: usize| match trajectory_block(model, &times[i..=i], opts, columns) {
        Err(e @ Error::InvalidParameter { .. }) => Some(e),
        _ => None,
    };
    let mut err = refused(times.len() - 1)?;
    let (mut lo, mut hi) = (0usize, times.len() - 1);
    if let Some(e) = refused(0) {
        return Some(e);
    }
    // times[lo] accepted, times[hi] refused
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        match refused(mid) {
            Some(e) => {
                hi = mid;
                err = e;
            }
            None => lo = mid,
        }
    }
    Some(err)
}

/// Every column at `times` (ascending, ≥ 0), through every phase to the
/// first impact: one row per time, in [`crate::motion::COLUMNS`] order,
/// with its phase; and the events up to the last time.
///
/// Errors: a negative or descending time; a time after the end of the
/// model; see [`motion::run`].
pub fn trajectory(model: &Model, times: &[Exact], opts: &Options) -> Result<Answer> {
    trajectory_of(model, times, opts, &all_columns())
}

/// Every column of a trajectory: [`motion::COLUMNS`] and `mode`.
pub fn all_columns() -> Vec<String> {
    let mut c: Vec<String> = motion::COLUMNS.iter().map(|s| s.to_string()).collect();
    c.push("mode".into());
    c
}

/// The columns named in `text` (comma-separated names of
/// [`motion::COLUMNS`] and `mode`, each at most once), in its order.
///
/// Errors: [`Error::InvalidParameter`] naming `columns`.
pub fn parse_columns(text: &str) -> Result<Vec<String>> {
    let all = all_columns();
    let mut out: Vec<String> = Vec::new();
    for c in text.split(',').map(str::trim) {
        if !all.iter().any(|a| a == c) {
            return Err(Error::invalid(
                "columns",
                c,
                format!("must be among {}", all.join(", ")),
            ));
        }
        if out.iter().any(|o| o == c) {
            return Err(Error::invalid("columns", c, "must be named only once"));
        }
        out.push(c.to_string());
    }
    Ok(out)
}

/// [`trajectory`] with only `columns` (see [`parse_columns`]): the others
/// are neither verified nor, where θ alone is asked (with `t` and `mode`),
/// computed.
///
/// Errors: as [`trajectory`].
pub fn trajectory_of(
    model: &Model,
    times: &[Exact],
    opts: &Options,
    columns: &[String],
) -> Result<Answer> {
    check_digits(opts.digits)?;
    check_part_at(model, opts)?;
    let b = trajectory_block(model, times, opts, columns)?;
    Ok(b.finish())
}

/// A trajectory's answer for some times, before its notes are complete.
struct Block {
    /// The answer, with the notes on the branch followed.
    ans: Answer,
    /// Notes on single rows (a time that cannot be told apart from an event's).
    row_notes: Vec<String>,
    /// The energy balance's largest drift and the energy's scale, for a
    /// dissipative motion.
    drift: Option<(Float, Float)>,
}

impl Block {
    /// The answer with its notes in order: the energy balance, the branch,
    /// the rows.
    fn finish(self) -> Answer {
        let mut ans = self.ans;
        let mut notes: Vec<String> = self.drift.iter().map(energy_note).collect();
        notes.append(&mut ans.notes);
        notes.extend(self.row_notes);
        ans.notes = notes;
        ans
    }
}

/// [`trajectory`] computed `block` rows at a time, so that memory stays
/// bounded however many times are asked: each block is a trajectory of its
/// own (the motion integrated to the block's last time at both working
/// precisions) and is handed to `sink` with its rows; the answer returned
/// carries everything but the rows — the events and notes of the motion to
/// the last time (those of the last block), followed by the notes on rows of
/// every block.
///
/// Errors: as [`trajectory`], and whatever `sink` returns.
pub fn trajectory_in_blocks(
    model: &Model,
    times: &[Exact],
    opts: &Options,
    columns: &[String],
    block: usize,
    mut sink: impl FnMut(&[Exact], Answer) -> Result<()>,
) -> Result<Answer> {
    check_digits(opts.digits)?;
    check_times(times)?;
    check_part_at(model, opts)?;
    let block = block.max(1);
    let chunks: Vec<&[Exact]> = times.chunks(block).collect();
    // the last block first: it follows the motion to the last time, so a
    // time past the end (or any other refusal of the motion) is found
    // before the other blocks are sunk (with the first of them, on a
    // machine with more than one core)
    let Some((last, rest)) = chunks.split_last() else {
        return trajectory_of(model, times, opts, columns);
    };
    // the blocks share nothing: as many at once as the machine has cores,
    // each on a thread of its own (with the caller's cancellation flag),
    // handed to the sink in order; memory grows by that many blocks
    let order: Vec<&[Exact]> = std::iter::once(*last).chain(rest.iter().copied()).collect();
    let width = block_threads()?;
    let mut last_block = None;
    let mut row_notes = Vec::new();
    let mut drift = None;
    for (w, window) in order.chunks(width).enumerate() {
        crate::cancel::check()?;
        let mut blocks = blocks_at_once(model, window, opts, columns).into_iter();
        if w == 0 {
            let b = match blocks.next().expect("the last block") {
                Ok(b) => b,
                Err(e @ Error::InvalidParameter { .. }) if !rest.is_empty() => {
                    return Err(first_refused_time(model, times, opts, columns).unwrap_or(e))
                }
                Err(e) => return Err(e),
            };
            drift = b.drift.clone();
            last_block = Some(b);
        }
        let chunks = if w == 0 { &window[1..] } else { window };
        for (chunk, b) in chunks.iter().zip(blocks) {
            let b = b?;
            row_notes.extend(b.row_notes);
            // the energy balance as held over every block's rows
            drift = match (drift, b.drift) {
                (Some(a), Some(d)) => Some(if d.0 > a.0 { d } else { a }),
                (a, d) => a.or(d),
            };
            sink(chunk, b.ans)?;
        }
    }
    let last_block = last_block.expect("the first window holds the last block");
    // the head: the last block's answer without its rows (not cloned)
    let mut last_ans = last_block.ans;
    let rows = std::mem::take(&mut last_ans.rows);
    let proved_rows = std::mem::take(&mut last_ans.proved_rows);
    let head = last_ans.clone();
    last_ans.rows = rows;
    last_ans.proved_rows = proved_rows;
    row_notes.extend(last_block.row_notes);
    sink(last, last_ans)?;
    Ok(Block {
        ans: head,
        row_notes,
        drift,
    }
    .finish())
}

/// The blocks of `window` in order, each computed on a thread of its own
/// with the caller's cancellation flag (a window of one: on this thread).
fn blocks_at_once(
    model: &Model,
    window: &[&[Exact]],
    opts: &Options,
    columns: &[String],
) -> Vec<Result<Block>> {
    if let [only] = window {
        return vec![trajectory_block(model, only, opts, columns)];
    }
    let flag = crate::cancel::current();
    std::thread::scope(|s| {
        let handles: Vec<_> = window
            .iter()
            .map(|chunk| {
                let flag = flag.clone();
                // the stack the Python package gives its worker (MPFR's
                // temporaries at thousands of digits)
                std::thread::Builder::new()
                    .stack_size(64 << 20)
                    .spawn_scoped(s, move || {
                        let _caches = crate::numeric::ThreadCaches;
                        if let Some(f) = flag {
                            crate::cancel::install(f);
                        }
                        trajectory_block(model, chunk, opts, columns)
                    })
            })
            .collect();
        handles
            .into_iter()
            .map(|h| match h {
                Ok(h) => h.join().unwrap_or_else(|e| std::panic::resume_unwind(e)),
                Err(e) => Err(Error::not_physical(format!(
                    "internal: cannot start a thread for a block of rows: {e}"
                ))),
            })
            .collect()
    })
}

/// How many blocks of a long table are computed at once: the machine's
/// cores (at most 8), or `CYLROLL_THREADS` (1 for one at a time).
///
/// Errors: `CYLROLL_THREADS` set to anything but a whole number from 1 to 64.
fn block_threads() -> Result<usize> {
    let n = crate::knobs::count(
        "CYLROLL_THREADS",
        64,
        "the blocks of a long table computed at once",
    )?;
    Ok(n.unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get().min(8))))
}

/// [`trajectory`]'s answer, its notes on single rows (a time that cannot be
/// told apart from an event's) apart.
fn trajectory_block(
    model: &Model,
    times: &[Exact],
    opts: &Options,
    columns: &[String],
) -> Result<Block> {
    check_digits(opts.digits)?;
    let mut runs = runs(model, opts, times.to_vec(), Until::LastTime);
    check_times_rounded(times, runs.caches.times.rounded())?;
    if model.starts_at_equilibrium() {
        return Err(infinite(model, "every time along the motion"));
    }
    let mut ans = empty_answer(Question::Trajectory, model, opts);
    ans.columns = columns.to_vec();
    // the table verified: t and θ (the events' rows need them), then the
    // other numeric columns asked, as indices of motion::COLUMNS
    let asked: Vec<usize> = columns
        .iter()
        .filter_map(|c| motion::COLUMNS.iter().position(|k| k == c))
        .collect();
    let mut idx = vec![0usize, 1];
    idx.extend(asked.iter().copied().filter(|&k| k > 1));
    let theta_only = idx.len() == 2;
    let exact_t = ladder::exact_times(times);
    runs.req.theta_only = theta_only;
    runs.req.derived_at_high = !theta_only;
    let (p1, _) = precisions(opts.digits, 0);
    let mut first = runs.at(p1, Run::Low)?;
    runs.resolve_sides(&mut first)?;
    let n_ev = first.events.len();
    let names: Vec<String> = idx
        .iter()
        .map(|&k| motion::COLUMNS[k].to_string())
        .collect();
    let n_rows = times.len();
    // the first run goes to the ladder (its rows become estimates); what
    // the answer needs of it besides is kept without its rows
    let phases: Vec<Phase> = first.rows.iter().map(|pt| pt.phase).collect();
    let first_rows = std::mem::take(&mut first.rows);
    let kept = first.clone();
    first.rows = first_rows;
    let (idx, exact_t) = (&idx, &exact_t);
    let mut table = laddered_short(&mut runs, first, &names, n_rows + n_ev, |mut m, run| {
        let p = m.prec();
        let shared = ladder::column_scales(model, p);
        // the events' times and angles, as rows of their own columns
        let mut ev = Vec::new();
        event_estimates(&m, &shared[0], &mut ev);
        let ev_rows: Vec<Vec<Estimate>> = ev
            .chunks(2)
            .map(|pair| {
                let mut row = vec![pair[0].clone(), pair[1].clone()];
                for &k in idx.iter().skip(2) {
                    row.push(Estimate::zero_shared(p, shared[k].clone()));
                }
                row
            })
            .collect();
        if theta_only {
            let tf = std::mem::take(&mut m.times);
            let mut out = Vec::with_capacity(2 * n_rows);
            for ((t, th), text) in tf
                .into_iter()
                .zip(ladder::theta_estimates(&mut m))
                .zip(exact_t)
            {
                let mut te = ladder::integrated_shared(t, shared[0].clone());
                te.exact_text = text.clone();
                out.push(te);
                out.push(th);
            }
            return Ok(Box::new(estimate_rows(out, 2).chain(ev_rows)) as RowIter);
        }
        // each row's estimates made from its point when the ladder judges
        // the row (the point's values moved into them)
        let rows = m.rows.into_iter().zip(exact_t).map(move |(pt, text)| {
            // a lower run's row that carries t and θ alone (the higher run
            // computes the rest, whose estimates decide alone): those two,
            // no placeholders for the others
            let cols = if pt.is_bare(run) { &idx[..2] } else { &idx[..] };
            let mut out = Vec::with_capacity(cols.len());
            ladder::push_point_estimates(pt, &shared, text.as_ref(), cols, run, &mut out);
            out
        });
        Ok(Box::new(rows.chain(ev_rows)) as RowIter)
    })?;
    let ev_rows = table.split_off(n_rows);
    let ev_vals: Vec<Verified> = ev_rows
        .into_iter()
        .flat_map(|r| r.into_iter().take(2))
        .collect();
    ans.events = events_of(&kept, &ev_vals);
    // each row in the order of the columns asked
    let at: Vec<usize> = asked
        .iter()
        .map(|&k| idx.iter().position(|&i| i == k).unwrap_or(0))
        .collect();
    let distinct = at.iter().enumerate().all(|(i, a)| !at[..i].contains(a));
    // every column in the order verified (a table of every column): as it is
    let identity = at.len() == idx.len() && at.iter().enumerate().all(|(i, &a)| a == i);
    let table: Vec<Vec<Verified>> = table
        .into_iter()
        .map(|row| {
            if identity {
                row
            } else if distinct {
                // each value moved to its place (a column asked once)
                let mut row: Vec<Option<Verified>> = row.into_iter().map(Some).collect();
                at.iter().filter_map(|&i| row[i].take()).collect()
            } else {
                at.iter().map(|&i| row[i].clone()).collect()
            }
        })
        .collect();
    ans.rows = if theta_only {
        ladder::theta_phases(&kept)
    } else {
        phases
    }
    .into_iter()
    .zip(table)
    .map(|(phase, values)| Row {
        values,
        phase,
        at_event: None,
    })
    .collect();
    let mut row_notes = Vec::new();
    for &(i, k) in &runs.at_events {
        ans.rows[i].at_event = Some(k);
        let e = &kept.events[k];
        row_notes.push(format!(
            "t = {} cannot be told apart from the {} at t = {} (not even at {} bits): its row is \
             the state at the event (positions and velocities are continuous there; the \
             forces and accelerations are those of the phase before)",
            times[i],
            e.kind.name().replace('_', " "),
            ans.events[k].t.text,
            runs.side_bits
        ));
    }
    ans.start_mode = Some(kept.start_mode);
    ans.end = kept.end;
    ans.routes = kept.routes.clone();
    ans.notes = branch_notes(&kept, opts);
    Ok(Block {
        ans,
        row_notes,
        drift: energy_drift(&kept),
    })
}

/// θ alone at `times`, verified like [`trajectory`]'s `theta` column but
/// without the other columns, and the phase of each time.
///
/// Errors: as [`trajectory`].
pub fn theta_at_times(
    model: &Model,
    times: &[Exact],
    opts: &Options,
) -> Result<(Vec<Verified>, Vec<Phase>)> {
    check_digits(opts.digits)?;
    let mut runs = runs(model, opts, times.to_vec(), Until::LastTime);
    check_times_rounded(times, runs.caches.times.rounded())?;
    check_part_at(model, opts)?;
    if model.starts_at_equilibrium() {
        return Err(infinite(model, "every time along the motion"));
    }
    runs.req.theta_only = true;
    let (p1, _) = precisions(opts.digits, 0);
    let mut first = runs.at(p1, Run::Low)?;
    runs.resolve_sides(&mut first)?;
    let phases = ladder::theta_phases(&first);
    let rows = laddered(
        &mut runs,
        first,
        &["theta".to_string()],
        times.len(),
        |mut m, _| Ok(ladder::theta_estimates(&mut m)),
    )?;
    Ok((
        rows.into_iter()
            .filter_map(|r| r.into_iter().next())
            .collect(),
        phases,
    ))
}
