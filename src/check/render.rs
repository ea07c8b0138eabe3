//! The report as text, CSV and JSON (numbers as decimal strings), and as a
//! JSON value with numbers for the Python binding.

use super::{CheckReport, EventVerdict, Transition};
use serde_json::{json, Value};

/// `max_rel` as text: `-` where undefined.
fn rel_text(r: Option<f64>) -> String {
    r.map_or("-".into(), |r| format!("{r:.3e}"))
}

/// err/limit as text: `-` where there is no finite ratio (the `mode`
/// column, whose failures are rows in another mode, ranked above every
/// ratio; a value off a zero limit, `--rtol 0 --atol 0`).
fn ratio_text(x: f64) -> String {
    if x.is_finite() {
        format!("{x:.3e}")
    } else {
        "-".into()
    }
}

/// err/limit in JSON: a number (a string with `strings`), `"-"` where
/// there is no finite ratio ([`ratio_text`]).
fn ratio_json(x: f64, strings: bool) -> Value {
    if x.is_finite() {
        num(x, strings)
    } else {
        Value::String("-".into())
    }
}

/// A number: a short decimal string, or (for Python) a JSON number; a
/// non-finite one is the string `inf`/`nan` either way.
fn num(x: f64, strings: bool) -> Value {
    if strings || !x.is_finite() {
        Value::String(if x.is_finite() {
            format!("{x:.3e}")
        } else {
            format!("{x}")
        })
    } else {
        json!(x)
    }
}

/// An exact tolerance: `{:e}` as a string, or a number.
fn tol_num(x: f64, strings: bool) -> Value {
    if strings {
        Value::String(format!("{x:e}"))
    } else {
        json!(x)
    }
}

/// A count: a string, or a number.
fn count(n: usize, strings: bool) -> Value {
    if strings {
        Value::String(n.to_string())
    } else {
        json!(n)
    }
}

fn transition_value(tr: &Transition, strings: bool) -> Value {
    json!({
        "from": tr.from,
        "to": tr.to,
        "rows": [count(tr.rows.0, strings), count(tr.rows.1, strings)],
        "t": [tr.t.0, tr.t.1],
        "theta": [num(tr.theta.0, strings), num(tr.theta.1, strings)],
    })
}

fn event_value(e: &EventVerdict, strings: bool) -> Value {
    json!({
        "kind": e.kind,
        "contact": e.contact,
        "mode": e.mode,
        "reference": e.reference.as_ref().map(|(t, th)| json!({"t": t, "theta": th})),
        "candidate": e.candidate.as_ref().map(|tr| transition_value(tr, strings)),
        "error": e.error.map(|x| num(x, strings)),
        "passed": e.passed,
        "why": e.why,
    })
}

fn event_line(e: &EventVerdict) -> String {
    let verdict = match e.passed {
        Some(true) => "PASS",
        Some(false) => "FAIL",
        None => "-",
    };
    let reference = e
        .reference
        .as_ref()
        .map_or("the reference: none".into(), |(t, th)| {
            format!("reference t = {t}, theta = {th}")
        });
    let cand = e.candidate.as_ref().map_or(String::new(), |tr| {
        format!(
            "; candidate rows {}-{} (t = {} .. {})",
            tr.rows.0, tr.rows.1, tr.t.0, tr.t.1
        )
    });
    let err = e
        .error
        .map_or(String::new(), |x| format!("; error {x:+.3e}"));
    format!(
        "{:<13} {:<8} -> {:<12} {reference}{cand}{err}: {verdict} ({})\n",
        e.kind,
        e.contact.as_deref().unwrap_or("-"),
        e.mode,
        e.why
    )
}

impl CheckReport {
    /// A plain-text table: per column, per phase, per event, the branch and
    /// the verdict.
    pub fn text(&self) -> String {
        let dropped = if self.rows_after_end > 0 {
            format!(
                "; {} after the end of the model left out",
                self.rows_after_end
            )
        } else {
            String::new()
        };
        let mut s = format!(
            "# cylroll check against case {} ({} rows{dropped}; oracle at {} digits)\n",
            self.case, self.rows, self.digits
        );
        let b = &self.branch;
        s.push_str(&format!(
            "# branch: requested {}, followed {}: {}\n",
            b.requested,
            b.followed.name(),
            b.why
        ));
        if let Some([a, e]) = &b.window {
            s.push_str(&format!(
                "# parting is lawful in the window [theta*, theta_s] = [{}, {}]\n",
                a.0, e.0
            ));
        }
        s.push_str(&format!(
            "# a value fails if |err| > atol + rtol*|oracle|: rtol {:e}, atol {:e} x the column's scale unless --tol sets them (the values applied below)\n",
            self.rtol, self.atol
        ));
        s.push_str(&format!(
            "{:<11} {:>9} {:>9} {:>10} {:>12} {:>10} {:>12} {:>10} {:>5} {:>9}\n",
            "column",
            "rtol",
            "atol",
            "max_abs",
            "at_t",
            "max_rel",
            "at_t",
            "err/limit",
            "bound",
            "failures"
        ));
        for c in &self.columns {
            let (rt, at) = c.tol.map_or(("-".to_string(), "-".to_string()), |t| {
                (format!("{:.2e}", t.rtol), format!("{:.2e}", t.atol))
            });
            s.push_str(&format!(
                "{:<11} {:>9} {:>9} {:>10.3e} {:>12} {:>10} {:>12} {:>10} {:>5} {:>9}\n",
                c.name,
                rt,
                at,
                c.max_abs,
                c.max_abs_t,
                rel_text(c.max_rel),
                c.max_rel_t,
                ratio_text(c.worst_ratio),
                c.worst_bound,
                c.failures
            ));
        }
        s.push_str("# phases of the reference on the candidate's rows (worst column: the largest err/limit)\n");
        for (k, ph) in self.phases.iter().enumerate() {
            let worst = self
                .columns
                .iter()
                .filter_map(|c| c.phases.get(k).map(|p| (c, p)))
                .max_by(|a, b| a.1.worst_ratio.total_cmp(&b.1.worst_ratio));
            let worst = worst.map_or(String::new(), |(c, p)| {
                if c.tol.is_none() {
                    format!("; worst {}: {} rows in another mode", c.name, p.failures)
                } else {
                    format!(
                        "; worst {}: err/limit {}, max_abs {:.3e} at t = {}",
                        c.name,
                        ratio_text(p.worst_ratio),
                        p.max_abs,
                        p.max_abs_t
                    )
                }
            });
            s.push_str(&format!(
                "phase {} {:<12} rows {}-{} ({}), t = {} .. {}: {}{worst}\n",
                k + 1,
                ph.tag,
                ph.row_first,
                ph.row_last,
                ph.rows,
                ph.t_first,
                ph.t_last,
                self.phase_verdict(k),
            ));
            for c in &self.columns {
                let Some(pc) = c.phases.get(k) else { continue };
                if pc.failures == 0 && pc.undecided == 0 {
                    continue;
                }
                s.push_str(&format!(
                    "  {:<11} failures {}, undecided {}, max_abs {:.3e} at t = {}\n",
                    c.name, pc.failures, pc.undecided, pc.max_abs, pc.max_abs_t
                ));
            }
        }
        s.push_str(&format!(
            "# events (event-tol {:e} rad of theta; the error: the oracle's theta at the nearer end of the candidate's bracket minus the event's, 0 inside it)\n",
            self.event_tol
        ));
        if !self.events.note.is_empty() {
            s.push_str(&format!("# {}\n", self.events.note));
        }
        for e in &self.events.list {
            s.push_str(&event_line(e));
        }
        if self.events.unlisted > 0 {
            s.push_str(&format!(
                "... and {} more transitions of the candidate the reference does not have\n",
                self.events.unlisted
            ));
        }
        match &self.first_failure {
            None if self.first_undecided.is_some() => {}
            None => s.push_str("PASS: every value within tolerance\n"),
            Some(f) if f.bound == "mode" => s.push_str(&format!(
                "FAIL: first at row {} (t = {}), column mode: candidate {} vs oracle {}\n",
                f.row, f.t, f.candidate, f.oracle
            )),
            Some(f) => s.push_str(&format!(
                "FAIL: first at row {} (t = {}), column {}: candidate {} vs oracle {}; |err| > {:.3e} ({} decides)\n",
                f.row, f.t, f.column, f.candidate, f.oracle, f.limit, f.bound
            )),
        }
        let bad_events: Vec<&EventVerdict> = self
            .events
            .list
            .iter()
            .filter(|e| e.passed == Some(false))
            .collect();
        if !bad_events.is_empty() {
            s.push_str(&format!(
                "FAIL: {} event(s) out of tolerance, the first: {} {}: {}\n",
                bad_events.len() + self.events.unlisted,
                bad_events[0].kind,
                bad_events[0].mode,
                bad_events[0].why
            ));
        } else if self.events.judged {
            s.push_str("PASS: every event within event-tol\n");
        }
        if !self.branch.lawful {
            s.push_str(&format!(
                "FAIL: the branch is not lawful: {}\n",
                self.branch.why
            ));
        }
        if let Some(f) = &self.first_undecided {
            let n: usize = self.columns.iter().map(|c| c.undecided).sum();
            s.push_str(&format!(
                "UNDECIDED: {n} value(s) lie within the oracle's error bound of their limit, the first at row {} (t = {}), column {}: candidate {} vs oracle {} (limit {:.3e}); raise --digits or loosen the tolerance\n",
                f.row, f.t, f.column, f.candidate, f.oracle, f.limit
            ));
        }
        for n in &self.notes {
            s.push_str(&format!("NOTE: {n}\n"));
        }
        if let Some((row, t)) = &self.first_after_end {
            let (kind, te) = self.end.clone().unwrap_or_default();
            s.push_str(&format!(
                "NOTE: {} row(s) after the end of the model (the {kind} at t = {te}) not compared, the first at row {row} (t = {t})\n",
                self.rows_after_end
            ));
        }
        s
    }

    /// `PASS`, `FAIL` or `UNDECIDED` for phase `k`.
    fn phase_verdict(&self, k: usize) -> &'static str {
        let cols = || self.columns.iter().filter_map(|c| c.phases.get(k));
        if cols().any(|p| p.failures > 0) {
            "FAIL"
        } else if cols().any(|p| p.undecided > 0) {
            "UNDECIDED"
        } else {
            "PASS"
        }
    }

    /// `pass`, `fail` or `undecided` (nothing fails, but a value's verdict
    /// rests on digits the oracle did not verify).
    pub fn verdict(&self) -> &'static str {
        match self.exit_code() {
            0 => "pass",
            1 => "fail",
            _ => "undecided",
        }
    }

    /// One CSV row per compared column (phase `all`), then one per column
    /// and phase of the reference (`1 stick/stick`, …).
    pub fn csv(&self) -> String {
        let mut s = String::from(
            "column,max_abs,max_abs_t,max_rel,max_rel_t,worst_err_over_limit,worst_bound,failures,undecided,rtol,atol,phase\n",
        );
        let tols = |c: &super::ColumnStats| {
            c.tol.map_or(("-".to_string(), "-".to_string()), |t| {
                (format!("{:e}", t.rtol), format!("{:.3e}", t.atol))
            })
        };
        for c in &self.columns {
            let (rt, at) = tols(c);
            s.push_str(&format!(
                "{},{:.3e},{},{},{},{},{},{},{},{rt},{at},all\n",
                c.name,
                c.max_abs,
                c.max_abs_t,
                rel_text(c.max_rel),
                c.max_rel_t,
                ratio_text(c.worst_ratio),
                c.worst_bound,
                c.failures,
                c.undecided
            ));
        }
        for (k, ph) in self.phases.iter().enumerate() {
            for c in &self.columns {
                let Some(pc) = c.phases.get(k) else { continue };
                let (rt, at) = tols(c);
                s.push_str(&format!(
                    "{},{:.3e},{},-,-,{},-,{},{},{rt},{at},{} {}\n",
                    c.name,
                    pc.max_abs,
                    pc.max_abs_t,
                    ratio_text(pc.worst_ratio),
                    pc.failures,
                    pc.undecided,
                    k + 1,
                    ph.tag
                ));
            }
        }
        s
    }

    /// The report as a JSON value: numbers as decimal strings when
    /// `strings` (the command line's JSON), else as numbers (the Python
    /// binding; a non-finite number is the string `inf`).
    pub fn value(&self, strings: bool) -> Value {
        let cols: Vec<Value> = self
            .columns
            .iter()
            .map(|c| {
                let phases: Vec<Value> = c
                    .phases
                    .iter()
                    .map(|p| {
                        json!({
                            "max_abs": num(p.max_abs, strings),
                            "max_abs_t": p.max_abs_t,
                            "worst_err_over_limit": ratio_json(p.worst_ratio, strings),
                            "failures": count(p.failures, strings),
                            "undecided": count(p.undecided, strings),
                            "passed": p.failures == 0 && p.undecided == 0,
                        })
                    })
                    .collect();
                json!({
                    "column": c.name,
                    "rtol": c.tol.map(|t| tol_num(t.rtol, strings)),
                    "atol": c.tol.map(|t| num(t.atol, strings)),
                    "scale": c.tol.map(|t| num(t.scale, strings)),
                    "tol_set": c.tol.is_some_and(|t| t.set),
                    "max_abs": num(c.max_abs, strings),
                    "max_abs_t": c.max_abs_t,
                    "max_rel": c.max_rel.map(|r| num(r, strings)),
                    "max_rel_t": c.max_rel_t,
                    "worst_err_over_limit": ratio_json(c.worst_ratio, strings),
                    "worst_bound": c.worst_bound,
                    "failures": count(c.failures, strings),
                    "undecided": count(c.undecided, strings),
                    "phases": phases,
                })
            })
            .collect();
        let failure = |f: &super::FirstFailure| {
            json!({"row": count(f.row, strings), "t": f.t, "column": f.column,
                   "candidate": f.candidate, "oracle": f.oracle,
                   "limit": num(f.limit, strings), "bound": f.bound})
        };
        let first = self.first_failure.as_ref().map(failure);
        let first_undecided = self.first_undecided.as_ref().map(failure);
        let phases: Vec<Value> = self
            .phases
            .iter()
            .enumerate()
            .map(|(k, p)| {
                json!({
                    "phase": count(k + 1, strings),
                    "mode": p.tag,
                    "t_first": p.t_first,
                    "t_last": p.t_last,
                    "rows": count(p.rows, strings),
                    "row_first": count(p.row_first, strings),
                    "row_last": count(p.row_last, strings),
                    "passed": self.phase_passed(k),
                    "verdict": self.phase_verdict(k).to_lowercase(),
                })
            })
            .collect();
        let b = &self.branch;
        let branch = json!({
            "requested": b.requested,
            "followed": b.followed.name(),
            "why": b.why,
            "lawful": b.lawful,
            "window": b.window.as_ref().map(|[a, e]| json!({
                "theta_indeterminate": a.0, "theta_s": e.0})),
            "parting": b.parting.as_ref().map(|p| json!({
                "found_by": p.by,
                "rows": [count(p.row_closed, strings), count(p.row_open, strings)],
                "t": [p.t_closed.to_string(), p.t_open.to_string()],
                "theta": [p.theta_closed.0, p.theta_open.0],
            })),
        });
        json!({
            "case": self.case,
            "passed": self.passed(),
            "verdict": self.verdict(),
            "rows": count(self.rows, strings),
            "rows_after_end": count(self.rows_after_end, strings),
            "first_after_end": self.first_after_end.as_ref().map(|(r, t)| json!({
                "row": count(*r, strings), "t": t})),
            "notes": self.notes,
            "end": self.end.as_ref().map(|(k, t)| json!({"event": k, "t": t})),
            "rtol": tol_num(self.rtol, strings),
            "atol": tol_num(self.atol, strings),
            "atol_unit": "the column's scale (each column's atol applied is under columns)",
            "event_tol": tol_num(self.event_tol, strings),
            "oracle_digits": count(self.digits as usize, strings),
            "branch": branch,
            "phases": phases,
            "columns": cols,
            "events_judged": self.events.judged,
            "events_note": self.events.note,
            "events": self.events.list.iter().map(|e| event_value(e, strings)).collect::<Vec<_>>(),
            "transitions": count(self.events.transitions, strings),
            "transitions_unlisted": count(self.events.unlisted, strings),
            "first_failure": first,
            "first_undecided": first_undecided,
        })
    }

    /// A JSON object (numbers as decimal strings).
    pub fn json(&self) -> String {
        serde_json::to_string_pretty(&self.value(true)).unwrap_or_default() + "\n"
    }
}
