//! Stacks of n ≥ 2 cylinders (paper footnote 3): which contact opens first,
//! and when, verified at two precisions.

pub mod spec;

use crate::error::{Error, Result};
use crate::exact::rational_text;
use crate::integrate::solve::{self, Event, Opts, Run, Sample, Watch};
use crate::integrate::{time_scale, TOL_GUARD};
use crate::mechanics::system::{self, Row, StackModel, System};
use crate::numeric::decimal::short;
use crate::numeric::verify::{ladder, Estimate, Verified};
use rug::{Float, Rational};
use spec::Spec;

/// Precision of the run that finds the sequence of events.
const SCAN_PREC: u32 = 128;

/// The name of constraint row `row` (its multiplier's force).
pub fn row_name(row: Row) -> String {
    let pair = |a: usize, b: usize| {
        if a < 10 && b < 10 {
            format!("{a}{b}")
        } else {
            format!("{a}_{b}")
        }
    };
    match row {
        Row::FloorNormal => "N1".into(),
        Row::FloorFriction => "F1".into(),
        Row::Hold => "hold1".into(),
        Row::Normal(j) => format!("N{}", pair(j + 1, j + 2)),
        Row::Friction(j) => format!("F{}", pair(j + 2, j + 1)),
        Row::Massless(k) => format!("massless{k}"),
    }
}

/// Where the first contact opened.
#[derive(Debug, Clone)]
pub struct StackOpening {
    /// The normal force that vanished (`N1`: the floor; `N23`: cylinders 2
    /// and 3; …).
    pub which: String,
    /// The state there.
    pub at: Sample,
    /// Half-width of the time bracket.
    pub t_err: Float,
}

/// A solved stack at one precision.
#[derive(Debug, Clone)]
pub struct StackSolution {
    /// Requested precision (bits).
    pub prec: u32,
    /// Internal working precision (bits).
    pub work_prec: u32,
    /// The first opening, if any before tmax.
    pub opening: Option<StackOpening>,
    /// Turning points passed before it: (line index j, state, time error).
    pub turning: Vec<(usize, Sample, Float)>,
    /// Names of the constraint rows (multiplier order).
    pub row_names: Vec<String>,
    /// Energy and conserved momenta at t = 0.
    pub e0: Float,
    /// See `e0`.
    pub p0: Vec<Float>,
    /// Largest |E − E0| / (|E0| + g Σ m r) over the samples and events.
    pub energy_drift: Float,
    /// Largest |p − p0| / (scale) over the samples and events.
    pub momentum_drift: Float,
    /// The integration record.
    pub run: Run,
}

/// Solves the stack at `prec` bits up to the first opening contact (or
/// `tmax`), sampling at `times`.
///
/// Errors: a start where a contact is already open (a normal force ≤ 0);
/// numerical failures.
pub fn solve_stack(spec: &Spec, prec: u32, times: &[Float]) -> Result<StackSolution> {
    let sm = &spec.model;
    if sm.starts_at_equilibrium() {
        return Err(Error::not_physical(
            "the stack starts at rest exactly on the vertical: it never moves",
        ));
    }
    let ts = time_scale(sm, prec);
    let o = Opts::for_prec(prec, TOL_GUARD, &ts);
    let requested = prec;
    let prec = o.prec;
    let mut sys = System::new(sm, prec)?;
    let (q0, v0) = sys.initial_state(sm)?;
    let a0 = sys.accel(&q0, &v0)?;
    let row_names: Vec<String> = sys.rows.iter().map(|r| row_name(*r)).collect();
    let mut events = Vec::new();
    for (i, row) in sys.rows.iter().enumerate() {
        if matches!(row, Row::FloorNormal | Row::Normal(_)) {
            let l = &a0.lambda[i];
            if !l.is_sign_positive() || l.is_zero() {
                return Err(Error::not_physical(format!(
                    "contact {} is open at the start: {} = {:.3e} <= 0",
                    row_names[i],
                    row_names[i],
                    l.to_f64()
                )));
            }
            events.push(Event {
                name: row_names[i].clone(),
                watch: Watch::Multiplier(i),
                terminal: true,
            });
        }
    }
    for j in 0..sm.n() - 1 {
        events.push(Event {
            name: format!("theta{}_dot", j + 1),
            watch: Watch::Rate(system::th(j)),
            terminal: false,
        });
    }
    let ts = time_scale(sm, prec);
    let tmax = match &spec.tmax {
        Some(t) => Float::with_val(prec, t),
        None => Float::with_val(prec, &ts * 200u32),
    };
    let run = solve::run(&mut sys, &q0, &v0, times, &tmax, &events, &o)?;
    let mut opening = None;
    let mut turning = Vec::new();
    for h in &run.hits {
        let ev = &events[h.event];
        if ev.terminal {
            opening = Some(StackOpening {
                which: ev.name.clone(),
                at: h.at.clone(),
                t_err: h.t_err.clone(),
            });
        } else if let Watch::Rate(i) = ev.watch {
            turning.push(((i - 4) / 3, h.at.clone(), h.t_err.clone()));
        }
    }
    let e0 = sys.energy(&q0, &v0);
    let p0 = sys.momenta(&q0, &v0);
    let (escale, pscale) = sys.drift_scales(&e0);
    let (energy_drift, momentum_drift) = sys.drifts(run.states(), &e0, &p0, &escale, &pscale);
    Ok(StackSolution {
        prec: requested,
        work_prec: prec,
        opening,
        turning,
        row_names,
        e0,
        p0,
        energy_drift,
        momentum_drift,
        run,
    })
}

/// The sequence of events of a solution, for comparing two precisions.
fn signature(s: &StackSolution) -> (Option<String>, Vec<usize>) {
    (
        s.opening.as_ref().map(|o| o.which.clone()),
        s.turning.iter().map(|t| t.0).collect(),
    )
}

/// An event signature in words: which contact opens, which bodies turn.
fn signature_text(sig: &(Option<String>, Vec<usize>)) -> String {
    let open = match &sig.0 {
        Some(w) => format!("contact {w} opens"),
        None => "no contact opens".to_string(),
    };
    if sig.1.is_empty() {
        format!("{open}, no turning point")
    } else {
        let t: Vec<String> = sig.1.iter().map(|j| format!("theta{}", j + 1)).collect();
        format!("{open}, turning points of {}", t.join(", "))
    }
}

fn describe(sm: &StackModel, tmax: &Option<Rational>) -> Vec<(String, String)> {
    let join = |v: &[Rational]| v.iter().map(rational_text).collect::<Vec<_>>().join(",");
    vec![
        ("n".into(), sm.n().to_string()),
        ("floor".into(), sm.floor.to_string()),
        (
            "contacts".into(),
            sm.contacts
                .iter()
                .map(|c| c.to_string())
                .collect::<Vec<_>>()
                .join(","),
        ),
        ("m".into(), join(&sm.m)),
        ("r".into(), join(&sm.r)),
        ("k".into(), join(&sm.k)),
        ("g".into(), rational_text(&sm.g)),
        (
            "theta0".into(),
            sm.theta0
                .iter()
                .map(|t| t.canonical())
                .collect::<Vec<_>>()
                .join(","),
        ),
        ("thetadot0".into(), join(&sm.thetadot0)),
        ("omega0".into(), rational_text(&sm.omega0)),
        (
            "tmax".into(),
            tmax.as_ref()
                .map(rational_text)
                .unwrap_or_else(|| "200*sqrt((r1+r2)/g)".into()),
        ),
    ]
}

/// The report of `cylroll verify --stack SPEC`.
pub fn report(spec: &Spec, digits: u32, json: bool) -> Result<String> {
    crate::oracle::check_digits(digits)?;
    let sm = &spec.model;
    let n = sm.n();
    let scan = solve_stack(spec, SCAN_PREC, &[])?;
    let sig = signature(&scan);
    let mut names: Vec<String> = Vec::new();
    let opened = scan.opening.is_some();
    names.push(if opened {
        "t_open".into()
    } else {
        "t_end".into()
    });
    for j in 0..n - 1 {
        names.push(format!("theta{}", j + 1));
    }
    for j in 0..n - 1 {
        names.push(format!("theta{}_dot", j + 1));
    }
    names.push("x1".into());
    names.push("phi1".into());
    let forces: Vec<usize> = scan
        .row_names
        .iter()
        .enumerate()
        .filter(|(_, nm)| !nm.starts_with("massless"))
        .map(|(i, _)| i)
        .collect();
    for &i in &forces {
        names.push(scan.row_names[i].clone());
    }
    for (k, (j, _, _)) in scan.turning.iter().enumerate() {
        names.push(format!("turn{}_t", k + 1));
        names.push(format!("turn{}_theta{}", k + 1, j + 1));
    }
    let name_refs: Vec<&str> = names.iter().map(|s| s.as_str()).collect();
    let mut last: Option<StackSolution> = None;
    let mut precs_used = Vec::new();
    let values: Vec<Verified> = ladder(digits, &name_refs, |p| {
        let s = solve_stack(spec, p, &[])?;
        if signature(&s) != sig {
            return Err(Error::NotConverged {
                quantity: "event sequence".into(),
                requested: digits,
                reached: format!("differs at {p} bits from the {SCAN_PREC}-bit scan"),
                detail: format!(
                    "{} at {p} bits, {} in the scan",
                    signature_text(&signature(&s)),
                    signature_text(&sig)
                ),
            });
        }
        let ts = time_scale(sm, p);
        let one = Float::with_val(p, 1u32);
        let rate = Float::with_val(p, &one / &ts);
        let mut fscale = Float::new(p);
        for m in &sm.m {
            fscale += Float::with_val(p, m);
        }
        fscale *= Float::with_val(p, &sm.g);
        let (st, terr) = match &s.opening {
            Some(o) => (o.at.clone(), o.t_err.clone()),
            None => (s.run.last.clone(), Float::new(p)),
        };
        // an angle or position error follows from the time error through the rate
        let prop = |x: &Float| Float::with_val(p, x.abs_ref()) * &terr;
        let mut out = vec![Estimate::new(st.t.clone(), terr.clone(), ts.clone())];
        for j in 0..n - 1 {
            out.push(Estimate::new(
                st.q[system::th(j)].clone(),
                prop(&st.v[system::th(j)]),
                one.clone(),
            ));
        }
        for j in 0..n - 1 {
            out.push(Estimate::new(
                st.v[system::th(j)].clone(),
                prop(&st.qdd[system::th(j)]),
                rate.clone(),
            ));
        }
        out.push(Estimate::new(
            st.q[system::X1].clone(),
            prop(&st.v[system::X1]),
            Float::with_val(p, &sm.r[0]),
        ));
        out.push(Estimate::new(
            st.q[system::PHI1].clone(),
            prop(&st.v[system::PHI1]),
            one.clone(),
        ));
        for &i in &forces {
            let ulps = Float::with_val(p, st.lambda[i].abs_ref()) >> (p as i32 - 4);
            let mut e = Estimate::new(st.lambda[i].clone(), ulps, fscale.clone());
            // the opening force is zero by construction, to the time bracket
            if Some(&s.row_names[i]) == s.opening.as_ref().map(|o| &o.which) {
                e.err = Float::with_val(p, &fscale * &terr) / &ts * 16u32;
            }
            out.push(e);
        }
        for (j, smp, err) in &s.turning {
            out.push(Estimate::new(smp.t.clone(), err.clone(), ts.clone()));
            out.push(Estimate::new(
                smp.q[system::th(*j)].clone(),
                Float::with_val(p, &smp.qdd[system::th(*j)] * err).abs() * err,
                one.clone(),
            ));
        }
        precs_used.push(p);
        last = Some(s);
        Ok(out)
    })?;
    let fin = last.ok_or_else(|| Error::not_physical("no run"))?;
    let p1 = precs_used
        .get(precs_used.len().saturating_sub(2))
        .copied()
        .unwrap_or(0);
    let p2 = fin.prec;
    let echo = describe(sm, &spec.tmax);
    let which = fin.opening.as_ref().map(|o| o.which.clone());
    let verdict = match &which {
        Some(w) if w == "N1" => {
            "the floor contact opens first: N1 = 0, cylinder 1 leaves the floor".to_string()
        }
        Some(w) => {
            let pair = w.trim_start_matches('N');
            format!(
                "contact {w} opens first: {w} = 0 (cylinders {} separate)",
                split_pair(pair)
            )
        }
        None => "no contact opens before tmax".to_string(),
    };
    let mut notes = vec![verdict.clone()];
    for (k, (j, smp, _)) in fin.turning.iter().enumerate() {
        notes.push(format!(
            "turning point {}: theta{}_dot = 0 at t = {} (turn{}_t)",
            k + 1,
            j + 1,
            crate::numeric::decimal::to_sig(&smp.t, 12),
            k + 1
        ));
    }
    notes.push(format!(
        "conservation at {p2} bits: max |E - E0|/scale = {}, max |p - p0|/scale = {} over {} conserved momenta; constraint drift {} of the units r, r/ts ({} projections)",
        short(&fin.energy_drift),
        short(&fin.momentum_drift),
        fin.p0.len(),
        short(&fin.run.max_drift),
        fin.run.projections
    ));
    notes.push(format!(
        "route 2 work at {p2} bits: {} steps ({} rejected), {} evaluations, largest extrapolation column {} (order {})",
        fin.run.stats.steps,
        fin.run.stats.rejected,
        fin.run.stats.evals,
        fin.run.stats.max_column,
        2 * fin.run.stats.max_column
    ));
    if json {
        let mut o = serde_json::Map::new();
        o.insert("command".into(), "verify --stack".into());
        let mut m = serde_json::Map::new();
        for (k, v) in &echo {
            m.insert(k.clone(), v.clone().into());
        }
        o.insert("model".into(), m.into());
        o.insert("digits_requested".into(), digits.to_string().into());
        o.insert("precisions".into(), format!("{p1}/{p2}").into());
        o.insert(
            "first_opening".into(),
            which.clone().unwrap_or_else(|| "none".into()).into(),
        );
        let mut verified = serde_json::Map::new();
        let mut errs = serde_json::Map::new();
        for v in &values {
            o.insert(v.name.clone(), v.text.clone().into());
            verified.insert(v.name.clone(), v.digits.to_string().into());
            errs.insert(v.name.clone(), v.err_text().into());
        }
        o.insert("digits_verified".into(), verified.into());
        o.insert("error_bounds".into(), errs.into());
        let mut cons = serde_json::Map::new();
        cons.insert("energy_drift".into(), short(&fin.energy_drift).into());
        cons.insert("momentum_drift".into(), short(&fin.momentum_drift).into());
        cons.insert("constraint_drift".into(), short(&fin.run.max_drift).into());
        o.insert("conservation".into(), cons.into());
        o.insert(
            "notes".into(),
            notes
                .iter()
                .map(|n| serde_json::Value::from(n.as_str()))
                .collect::<Vec<_>>()
                .into(),
        );
        return serde_json::to_string_pretty(&serde_json::Value::Object(o))
            .map(|s| s + "\n")
            .map_err(|e| Error::not_physical(format!("json: {e}")));
    }
    let mut out = String::new();
    out.push_str(&format!(
        "# cylroll verify --stack — {}\n",
        echo.iter()
            .map(|(k, v)| format!("{k}={v}"))
            .collect::<Vec<_>>()
            .join(" ")
    ));
    out.push_str(&format!(
        "# second route only (time integration of the Lagrange-multiplier equations); {digits} significant digits requested, each value verified at {p1} and {p2} bits\n"
    ));
    out.push_str(&format!(
        "first_opening = {}\n",
        which.unwrap_or_else(|| "none".into())
    ));
    let w = values.iter().map(|v| v.name.len()).max().unwrap_or(0);
    for v in &values {
        let note = if v.digits == 0 {
            format!("[indistinguishable from 0: |x| <= {}]", v.err_text())
        } else {
            format!("[{} digits; |err| <= {}]", v.digits, v.err_text())
        };
        out.push_str(&format!("{:w$} = {}  {}\n", v.name, v.text, note, w = w));
    }
    for nt in &notes {
        out.push_str(&format!("note: {nt}\n"));
    }
    Ok(out)
}

fn split_pair(p: &str) -> String {
    if let Some((a, b)) = p.split_once('_') {
        format!("{a} and {b}")
    } else if p.len() == 2 {
        format!("{} and {}", &p[..1], &p[1..])
    } else {
        p.to_string()
    }
}

/// Solves a stack of cylinders described by `spec` (see [`spec::HELP`];
/// `"help"` returns that text) and returns the report (`json`: as a JSON
/// object with decimal strings).
///
/// Errors: a bad SPEC ([`Error::InvalidParameter`]), a start where a contact
/// is already open, digits that cannot be verified.
pub fn stack_report(spec: &str, digits: u32, json: bool) -> Result<String> {
    if spec.trim() == "help" {
        return Ok(spec::HELP.to_string());
    }
    let sp = spec::parse(spec)?;
    report(&sp, digits, json)
}
