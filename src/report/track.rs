//! Trajectories sampled at their events: a grid of times plus, for every
//! event, a time just before and just after it (10⁻⁹ τ away, far inside
//! the digits a figure shows; farther where the event's time is verified to
//! so few digits that its uncertainty comes near that: [`gap`]), so that
//! every curve reaches each event from both sides and breaks there.

use crate::error::{Error, Result};
use crate::exact::Exact;
use crate::model::Model;
use crate::motion::{Kind, COLUMNS};
use crate::oracle::{self, Answer, Options};
use rug::{Integer, Rational};

/// How far before and after an event its two samples lie (τ), at least
/// (see [`gap`]).
pub const EVENT_GAP: f64 = 1e-9;

/// How far from an event time verified as `t` its two samples lie: 10⁻⁹ τ,
/// or 10⁻ᵏ τ with k the largest power that keeps them at least ten units of
/// the time's last verified digit away (so that a sample is on its side of
/// the event whichever way the printed digits were rounded).
pub fn gap(t: &crate::numeric::verify::Verified) -> Rational {
    let x = t.value.to_f64().abs().max(1e-300);
    let last = x.log10().floor() as i64 - i64::from(t.digits) + 1;
    let k = (-(last + 1)).clamp(1, 9);
    Rational::from((
        Integer::from(1),
        Integer::from(Integer::u_pow_u(10, k as u32)),
    ))
}

/// One event of a track.
#[derive(Debug, Clone)]
pub struct Ev {
    /// What happened.
    pub kind: Kind,
    /// The contact (`floor`, `contact`; empty for an impact).
    pub which: String,
    /// Time and angle (f64 of the verified values).
    pub t: f64,
    /// θ at the event.
    pub theta: f64,
    /// The phase entered (`flight`, `stick/slip+`; empty: the end).
    pub phase: String,
}

/// A trajectory sampled at its events.
#[derive(Debug, Clone)]
pub struct Track {
    /// Rows in [`COLUMNS`] order (f64 of verified values).
    pub rows: Vec<Vec<f64>>,
    /// The phase of each row.
    pub phases: Vec<String>,
    /// The events (from the separation answer).
    pub events: Vec<Ev>,
    /// The separation answer.
    pub answer: Answer,
}

impl Track {
    /// A column by name as (t, value) points, a NaN point between two rows
    /// of different phases (the line breaks at every phase boundary).
    pub fn col(&self, name: &str) -> (Vec<(f64, f64)>, Vec<String>) {
        let i = COLUMNS.iter().position(|c| *c == name).unwrap_or(0);
        self.map(|r| r[i])
    }

    /// A function of the row (its values in [`COLUMNS`] order) as (t,
    /// value) points, broken at every phase boundary like [`Track::col`].
    pub fn map(&self, f: impl Fn(&[f64]) -> f64) -> (Vec<(f64, f64)>, Vec<String>) {
        let mut pts = Vec::new();
        let mut ph = Vec::new();
        for (k, r) in self.rows.iter().enumerate() {
            if k > 0 && self.phases[k] != self.phases[k - 1] {
                pts.push((f64::NAN, f64::NAN));
                ph.push(String::new());
            }
            pts.push((r[0], f(r)));
            ph.push(self.phases[k].clone());
        }
        (pts, ph)
    }

    /// A verified value of the separation answer, as f64.
    pub fn value(&self, name: &str) -> Option<f64> {
        self.answer.value(name).map(|v| v.value.to_f64())
    }

    /// The first event of a kind.
    pub fn event(&self, kind: Kind) -> Option<&Ev> {
        self.events.iter().find(|e| e.kind == kind)
    }
}

/// A decimal with at most 5 decimals at or below `x` ≥ 0.
fn grid_time(x: f64) -> Rational {
    let n = (x * 1e5).floor().max(0.0) as i64;
    Rational::from((Integer::from(n), Integer::from(100_000)))
}

/// The events of an answer.
pub fn events(a: &Answer) -> Vec<Ev> {
    a.events
        .iter()
        .map(|e| Ev {
            kind: e.kind,
            which: e.which.map_or(String::new(), |w| w.name().to_string()),
            t: e.t.value.to_f64(),
            theta: e.theta.value.to_f64(),
            phase: e.phase.map_or(String::new(), |p| p.tag()),
        })
        .collect()
}

/// The model's motion from its start to `until` (the end of the model if
/// None, else the first event of that kind), sampled at `n` + 1 grid times
/// and on both sides of every event, verified to `digits`.
pub fn track(model: &Model, opts: &Options, n: usize, until: Option<Kind>) -> Result<Track> {
    let answer = oracle::separation(model, opts)?;
    let evs = events(&answer);
    let last_ev = match until {
        Some(k) => evs.iter().position(|e| e.kind == k),
        None => evs.len().checked_sub(1),
    }
    .ok_or_else(|| Error::not_physical("the motion has no event to end the figure at"))?;
    let t_end = evs[last_ev].t;
    let exact_of = |v: &crate::numeric::verify::Verified| -> Result<Rational> {
        Exact::parse("t", &v.text, false)?
            .as_rational()
            .cloned()
            .ok_or_else(|| Error::not_physical("an event time is not a decimal"))
    };
    let mut times: Vec<Rational> = Vec::new();
    for (k, e) in answer.events.iter().enumerate().take(last_ev + 1) {
        let te = exact_of(&e.t)?;
        let g = gap(&e.t);
        times.push(Rational::from(&te - &g));
        if k < last_ev {
            times.push(Rational::from(&te + &g));
        }
    }
    let n = n.max(2);
    for i in 0..n {
        let t = grid_time(t_end * i as f64 / n as f64);
        let tf = t.to_f64();
        if evs.iter().all(|e| (e.t - tf).abs() > 1e-4) {
            times.push(t);
        }
    }
    times.sort();
    times.dedup();
    let exact: Vec<Exact> = times.into_iter().map(Exact::rational).collect();
    let tr = oracle::trajectory(model, &exact, opts)?;
    let rows = tr
        .rows
        .iter()
        .map(|r| r.values.iter().map(|v| v.value.to_f64()).collect())
        .collect();
    let phases = tr.rows.iter().map(|r| r.phase.tag()).collect();
    let events = evs.into_iter().filter(|e| e.t <= t_end).collect();
    Ok(Track {
        rows,
        phases,
        events,
        answer,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn samples_keep_clear_of_an_event_s_last_digit() {
        let v = |text: &str, digits: u32| crate::numeric::verify::Verified {
            name: "t".into(),
            value: rug::Float::with_val(64, rug::Float::parse(text).expect("number")),
            text: text.into(),
            digits,
            err_bound: rug::Float::with_val(64, 0),
            precs: (64, 128),
        };
        // 12 digits of t = 4.156…: the last digit is 1e-11, the gap 1e-9
        assert_eq!(
            gap(&v("4.15605677802", 12)),
            Rational::from((1, 1_000_000_000))
        );
        // 8 digits: the last digit is 1e-7, the gap 1e-6
        assert_eq!(gap(&v("4.1560568", 8)), Rational::from((1, 1_000_000)));
    }
}
