//! Per-event verdicts: the candidate's changes of mode matched with the
//! reference's events entering the same mode, in order.

use super::{EventVerdict, Events, PhaseInfo, Transition};
use crate::oracle::Answer;

/// Unmatched transitions of the candidate listed one by one.
const LISTED: usize = 20;

/// The error in θ of a candidate's transition against an event at
/// (`t`, `theta`): the oracle's θ at the nearer end of the candidate's
/// bracket minus the event's θ, 0 when the event lies inside the bracket.
pub fn error(tr: &Transition, t: f64, theta: f64) -> f64 {
    if t < tr.t_f.0 {
        tr.theta.0 - theta
    } else if t > tr.t_f.1 {
        tr.theta.1 - theta
    } else {
        0.0
    }
}

/// A time as the candidate wrote it, exactly.
fn written(s: &str) -> Option<rug::Rational> {
    crate::exact::Exact::parse("t", s, false)
        .ok()
        .map(|e| e.coef)
}

/// Where the times `a` <= `b` (as written) lie relative to the event time
/// `ev`, known to within its error bound, exactly: 1 after it, -1 before
/// it, 0 around it or within its error (undecided: the caller's binary64
/// reading stands), or a time that cannot be read.
fn exact_side_of(a: &str, b: &str, ev: &crate::numeric::verify::Verified) -> i32 {
    let (Some(a), Some(b), Some(t), Some(e)) = (
        written(a),
        written(b),
        ev.value.to_rational(),
        ev.err_bound.to_rational(),
    ) else {
        return 0;
    };
    if a > rug::Rational::from(&t + &e) {
        1
    } else if b < rug::Rational::from(&t - &e) {
        -1
    } else {
        0
    }
}

/// Where the candidate's bracket (its two rows' times) lies relative to
/// the event ([`exact_side_of`]).
fn exact_side(tr: &Transition, ev: &crate::numeric::verify::Verified) -> i32 {
    exact_side_of(&tr.t.0, &tr.t.1, ev)
}

/// Distance in time from `t` to a transition's bracket.
fn distance(tr: &Transition, t: f64) -> f64 {
    if t < tr.t_f.0 {
        tr.t_f.0 - t
    } else if t > tr.t_f.1 {
        t - tr.t_f.1
    } else {
        0.0
    }
}

/// The verdicts on the events of `followed` (the reference on the branch
/// followed) for a candidate with the `transitions` (of `n_transitions`;
/// `has_mode`: whether it has a `mode` column) whose rows fall into
/// `phases`.
pub fn judge(
    followed: &Answer,
    transitions: &[Transition],
    n_transitions: usize,
    has_mode: bool,
    phases: &[PhaseInfo],
    tol: f64,
) -> Events {
    let (t0, t1) = (
        phases.first().map_or(0.0, |p| p.t_first_f),
        phases.last().map_or(0.0, |p| p.t_last_f),
    );
    let mut out = Events {
        judged: has_mode,
        note: if has_mode {
            String::new()
        } else {
            "the candidate has no mode column: its events are not judged (the reference's are \
             listed)"
                .into()
        },
        transitions: n_transitions,
        ..Events::default()
    };
    let mut used = vec![false; transitions.len()];
    let mut next = 0usize;
    let mut cur = followed.start_mode.map(|m| m.tag());
    // the times of the mode-changing events, to tell whether a candidate row
    // falls in the phase an event enters
    let changes: Vec<f64> = {
        let mut c = cur.clone();
        let mut v = Vec::new();
        for e in &followed.events {
            if let Some(ph) = e.phase {
                if c.as_deref() != Some(ph.tag().as_str()) {
                    v.push(e.t.value.to_f64());
                    c = Some(ph.tag());
                }
            }
        }
        v
    };
    let mut k_change = 0usize;
    for e in &followed.events {
        let (t, theta) = (e.t.value.to_f64(), e.theta.value.to_f64());
        let mut v = EventVerdict {
            kind: e.kind.name().to_string(),
            contact: e.which.map(|w| w.name().to_string()),
            mode: e.phase.map_or("-".to_string(), |p| p.tag()),
            reference: Some((e.t.text.clone(), e.theta.text.clone())),
            reference_f: Some((t, theta)),
            candidate: None,
            error: None,
            passed: None,
            why: String::new(),
        };
        let Some(ph) = e.phase else {
            v.why = "the end of the model: not judged".into();
            out.list.push(v);
            continue;
        };
        let tag = ph.tag();
        if cur.as_deref() == Some(tag.as_str()) {
            v.why = "no change of mode: not judged by the mode column".into();
            out.list.push(v);
            continue;
        }
        cur = Some(tag.clone());
        let next_change = changes.get(k_change + 1).copied().unwrap_or(f64::INFINITY);
        k_change += 1;
        if !has_mode {
            v.why = "not judged (no mode column)".into();
            out.list.push(v);
            continue;
        }
        // outside the candidate's rows, decided on the times as written
        // (binary64 put an event 1e-16 s past the last row inside them)
        let outside = match (phases.first(), phases.last()) {
            (Some(f), Some(l)) => match exact_side_of(&f.t_first, &l.t_last, &e.t) {
                0 => t > t1 || t < t0,
                _ => true,
            },
            _ => t > t1 || t < t0,
        };
        if outside {
            v.why = "outside the candidate's rows: not judged".into();
            out.list.push(v);
            continue;
        }
        // the candidate's transition into the same mode nearest in time,
        // after the one matched last
        let best = transitions
            .iter()
            .enumerate()
            .skip(next)
            .filter(|(i, tr)| !used[*i] && super::mode_matches(&tr.to, &tag))
            .min_by(|a, b| distance(a.1, t).total_cmp(&distance(b.1, t)))
            .map(|(i, _)| i);
        match best {
            Some(i) => {
                used[i] = true;
                next = i + 1;
                let tr = &transitions[i];
                let mut err = error(tr, t, theta);
                // inside or not decided exactly (the candidate's times as
                // written against the event's time): binary64 put an event
                // 1e-16 s past the bracket inside it
                let side = exact_side(tr, &e.t);
                let unresolved = err == 0.0 && side != 0;
                if unresolved {
                    // outside by less than binary64 resolves in θ: the two
                    // θ compared were each rounded to nearest, so their
                    // difference, 0 in binary64, is at most an ulp of θ
                    err = f64::from(side) * 2.0 * f64::EPSILON * theta.abs().max(f64::MIN_POSITIVE);
                }
                let ok = err.abs() <= tol;
                v.why = if err == 0.0 {
                    "the event lies inside the candidate's bracket".into()
                } else if unresolved {
                    format!(
                        "the candidate's bracket is {} the event by less than {:.3e} rad of \
                         theta (binary64's resolution of the angles compared; {} event-tol {:e})",
                        if side > 0 { "after" } else { "before" },
                        err.abs(),
                        if ok { "within" } else { "beyond" },
                        tol
                    )
                } else {
                    format!(
                        "the candidate's bracket is {} the event by {:.3e} rad of theta ({} \
                         event-tol {:e})",
                        if err > 0.0 { "after" } else { "before" },
                        err.abs(),
                        if ok { "within" } else { "beyond" },
                        tol
                    )
                };
                v.error = Some(err);
                v.passed = Some(ok);
                v.candidate = Some(tr.clone());
            }
            None => {
                let has_row = phases
                    .iter()
                    .any(|p| p.tag == tag && p.t_first_f >= t && p.t_first_f < next_change);
                if has_row {
                    v.passed = Some(false);
                    v.why = format!("the candidate never enters {tag} here");
                } else {
                    v.why = format!(
                        "no row of the candidate falls in the phase it enters ({tag} lies between \
                         two rows): not judged"
                    );
                }
            }
        }
        out.list.push(v);
    }
    if has_mode {
        let mut listed = 0usize;
        for (i, tr) in transitions.iter().enumerate() {
            if used[i] {
                continue;
            }
            if listed == LISTED {
                out.unlisted += 1;
                continue;
            }
            listed += 1;
            out.list.push(EventVerdict {
                kind: "spurious".into(),
                contact: None,
                mode: tr.to.clone(),
                reference: None,
                reference_f: None,
                candidate: Some(tr.clone()),
                error: None,
                passed: Some(false),
                why: format!(
                    "the candidate enters {} from {} where the reference has no such event",
                    tr.to, tr.from
                ),
            });
        }
        out.unlisted += n_transitions - transitions.len();
    }
    out
}
