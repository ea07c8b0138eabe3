//! `--rigorous`: the interval enclosures attached to an answer, where the
//! closed forms of a conservative phase prove them.

use super::Common;
use cylroll::error::Result;
use cylroll::exact::Exact;
use cylroll::model::Model;
use cylroll::oracle::rigorous::{enclosure_why, prove_with, stick_end_proved, unsupported, Proved};
use cylroll::oracle::{Answer, Oracle};

/// `--rigorous` for `time`, `forces` and `trajectory`: the ideal models.
pub fn supported(common: &Common, model: &Model) -> Result<()> {
    if common.rigorous && model.has_coulomb() {
        return Err(unsupported("with friction"));
    }
    Ok(())
}

fn proves_less(v: &[Proved], digits: u32) -> bool {
    v.iter()
        .any(|x| x.shown.digits < digits && x.shown.text != "0")
}

/// Places an enclosure beside the value of the same name.
fn attach(ans: &mut Answer, name: &str, pv: Option<Proved>) {
    ans.proved.resize(ans.values.len(), None);
    if let Some(i) = ans.values.iter().position(|v| v.name == name) {
        ans.proved[i] = pv;
    }
}

/// θs and t_s of an ideal model; with friction, where sticking ends.
pub fn separation(model: &Model, ans: &mut Answer) {
    let digits = ans.digits;
    ans.proved.resize(ans.values.len(), None);
    let Some(ideal) = model.ideal() else {
        match stick_end_proved(model, ans, digits) {
            Ok(slots) => {
                let mut names = Vec::new();
                for (at, v, pv) in slots {
                    if pv.is_none() {
                        ans.notes
                            .push(format!("{} is not enclosed: verified digits only", v.name));
                    } else {
                        names.push(v.name.clone());
                    }
                    match at {
                        Some(i) => ans.proved[i] = pv,
                        None => {
                            ans.values.push(v);
                            ans.proved.push(pv);
                        }
                    }
                }
                if !names.is_empty() {
                    ans.notes.push(format!(
                        "--rigorous encloses {}: where sticking ends, a root of a polynomial in \
                         cos theta while both contacts stick (the rolling model's closed forms), \
                         and the time to it; the phases after it are integrated and verified only",
                        names.join(" and ")
                    ));
                }
            }
            Err(why) => ans.notes.push(format!(
                "--rigorous: nothing is enclosed ({why}); every value is verified only"
            )),
        }
        return;
    };
    if ans.value("theta_s").is_none() {
        ans.notes.push(
            "--rigorous: nothing is enclosed (the motion does not separate); every value is \
             verified only"
                .into(),
        );
        return;
    }
    let has_ts = ans.value("t_s").is_some();
    let res = Oracle::new(&ideal, digits).and_then(|mut o| {
        prove_with(
            digits,
            |p| o.rigorous_separation(p),
            |(th, ts)| {
                th.shown.digits < digits || ts.as_ref().is_ok_and(|t| t.shown.digits < digits)
            },
        )
    });
    match res {
        Ok((th, ts)) => {
            branch_point(&ideal, &th, ans);
            attach(ans, "theta_s", Some(th));
            if has_ts {
                match ts {
                    Ok(t) => attach(ans, "t_s", Some(t)),
                    Err(why) => ans
                        .notes
                        .push(format!("t_s is not enclosed ({why}): verified digits only")),
                }
            }
        }
        Err(e) => ans.notes.push(format!(
            "theta_s is not enclosed ({}): verified digits only",
            enclosure_why(&e)
        )),
    }
    let what = if ans
        .proved
        .get(
            ans.values
                .iter()
                .position(|v| v.name == "theta_indeterminate")
                .unwrap_or(usize::MAX),
        )
        .is_some_and(Option::is_some)
    {
        "theta_s and t_s of the closed branch and the branch point theta_indeterminate, \
         t_indeterminate"
    } else {
        "theta_s and t_s of the closed branch"
    };
    ans.notes.push(format!(
        "--rigorous encloses {what}; the other values are verified only"
    ));
}

/// θ*, t* of an ideal model, proved beside the proved θs.
fn branch_point(ideal: &cylroll::model::Ideal, theta_s: &Proved, ans: &mut Answer) {
    let Some(start) = ans.value("theta_indeterminate").map(|v| v.value.clone()) else {
        return;
    };
    let digits = ans.digits;
    let has_t = ans.value("t_indeterminate").is_some();
    let res = Oracle::new(ideal, digits).and_then(|mut o| {
        prove_with(
            digits,
            |p| o.rigorous_branch_point(&start, &theta_s.iv, p),
            |(th, t)| th.shown.digits < digits || t.as_ref().is_ok_and(|t| t.shown.digits < digits),
        )
    });
    match res {
        Ok((th, t)) => {
            attach(ans, "theta_indeterminate", Some(th));
            if has_t {
                match t {
                    Ok(t) => attach(ans, "t_indeterminate", Some(t)),
                    Err(why) => ans.notes.push(format!(
                        "t_indeterminate is not enclosed ({why}): verified digits only"
                    )),
                }
            }
        }
        Err(e) => ans.notes.push(format!(
            "theta_indeterminate is not enclosed ({}): verified digits only",
            enclosure_why(&e)
        )),
    }
}

/// t(θ) of an ideal model.
pub fn time(model: &Model, theta: &Exact, ans: &mut Answer) {
    let digits = ans.digits;
    let Some(ideal) = model.ideal() else { return };
    let res = Oracle::new(&ideal, digits).and_then(|mut o| {
        prove_with(
            digits,
            |p| o.rigorous_time(theta, p),
            |v| v.shown.digits < digits,
        )
    });
    match res {
        Ok(pv) => attach(ans, "t", Some(pv)),
        Err(e) => {
            ans.proved.resize(ans.values.len(), None);
            ans.notes.push(format!(
                "t is not enclosed ({}): verified digits only",
                enclosure_why(&e)
            ))
        }
    }
}

/// The forces of an ideal model at θ.
pub fn forces(model: &Model, theta: &Exact, ans: &mut Answer) {
    let digits = ans.digits;
    ans.proved.resize(ans.values.len(), None);
    let Some(ideal) = model.ideal() else { return };
    let res = Oracle::new(&ideal, digits).and_then(|mut o| {
        prove_with(
            digits,
            |p| o.rigorous_forces(theta, p),
            |v| {
                v.iter().any(|x| {
                    x.as_ref()
                        .is_some_and(|x| x.shown.digits < digits && x.shown.text != "0")
                })
            },
        )
    });
    match res {
        Ok(pv) => {
            for p in pv.into_iter().flatten() {
                let name = p.name.clone();
                attach(ans, &name, Some(p));
            }
        }
        Err(e) => ans.notes.push(format!(
            "the forces are not enclosed ({}): verified digits only",
            enclosure_why(&e)
        )),
    }
}

/// The rows of an ideal model in the closed branch enclosed, block after
/// block of a trajectory (the flight is verified only).
#[derive(Default)]
pub struct RowsProof {
    oracle: Option<Oracle>,
    /// Why the enclosures stopped (then no later row is enclosed).
    failed: Option<String>,
    /// Rows in flight (verified only).
    flight: usize,
    /// Some row was enclosed.
    proved: bool,
}

impl RowsProof {
    /// Encloses the rows of `ans` (a block of a trajectory at `times`).
    pub fn block(&mut self, model: &Model, times: &[Exact], ans: &mut Answer) {
        let digits = ans.digits;
        if self.failed.is_some() {
            return;
        }
        let Some(ideal) = model.ideal() else { return };
        if self.oracle.is_none() {
            match Oracle::new(&ideal, digits) {
                Ok(o) => self.oracle = Some(o),
                Err(e) => {
                    self.failed = Some(format!(
                        "the rows are not enclosed ({}): verified digits only",
                        enclosure_why(&e)
                    ));
                    return;
                }
            }
        }
        let Some(o) = self.oracle.as_mut() else {
            return;
        };
        let mut rows = Vec::new();
        for (t, row) in times.iter().zip(&ans.rows) {
            if row.phase.is_flight() {
                self.flight += 1;
                rows.push(Vec::new());
                continue;
            }
            match prove_with(digits, |p| o.rigorous_row(t, p), |v| proves_less(v, digits)) {
                Ok(r) => {
                    self.proved = true;
                    rows.push(r)
                }
                Err(e) => {
                    self.failed = Some(format!(
                        "the rows from t = {t} on are not enclosed ({}): verified digits only",
                        enclosure_why(&e)
                    ));
                    break;
                }
            }
        }
        ans.proved_rows = rows;
    }

    /// The notes on the enclosures, added to the answer's.
    pub fn notes(&self, ans: &mut Answer) {
        if let Some(f) = &self.failed {
            ans.notes.push(f.clone());
        }
        if self.flight > 0 {
            ans.notes.push(format!(
                "--rigorous: the {} row(s) in flight are verified only (not enclosed)",
                self.flight
            ));
        }
        if self.proved {
            ans.notes.push(
                "--rigorous encloses the columns t ... y2 and F1 ... N12 of the rows before \
                 separation; the velocities, slip speeds and work are verified only"
                    .into(),
            );
        }
    }
}
