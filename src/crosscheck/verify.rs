//! `cylroll verify`: both routes on a set of cases, and the digits to which
//! they agree, per case and quantity.

use super::{two_cylinder, TwoOpts, TwoRun, TwoState};
use crate::error::{Error, Result};
use crate::exact::Exact;
use crate::model::{Contact, Floor, Ideal, Params, Start};
use crate::numeric::decimal::short;
use crate::numeric::verify::{ladder, Estimate, Verified};
use crate::oracle::{Oracle, TRAJECTORY_COLUMNS};
use rug::ops::Pow;
use rug::{Float, Rational};
use std::time::Instant;

/// One case of the verification set.
#[derive(Debug, Clone)]
pub struct VerifyCase {
    /// Short name.
    pub name: String,
    /// The model.
    pub model: Ideal,
}

fn q(s: &str) -> Rational {
    // the literals below are valid by construction
    Exact::parse("case", s, false)
        .map(|e| e.coef)
        .unwrap_or_default()
}

fn unequal() -> Params {
    Params {
        m1: q("3"),
        m2: q("1.25"),
        r1: q("0.7"),
        r2: q("1/3"),
        k1: q("0.4"),
        k2: q("0.9"),
        g: q("9.81"),
    }
}

fn start(theta0: &str, td0: &str, w0: &str) -> Start {
    Start {
        theta0: Exact::rational(q(theta0)),
        thetadot0: q(td0),
        omega0: q(w0),
    }
}

/// The built-in verification set: every contact model (unequal masses,
/// radii and inertia factors, from rest at θ0 = 1/10), a bobbin (k2 = 3/2)
/// on a smaller cylinder, starts with θ̇0 ≠ 0 and ω0 ≠ 0 on a rolling and on
/// a frictionless floor, and the paper's identical solid cylinders falling
/// to the left (θ0 < 0, which the first route solves as a mirror image).
pub fn cases() -> Vec<VerifyCase> {
    let mut out = Vec::new();
    let mut push = |name: String, m: Result<Ideal>| {
        if let Ok(model) = m {
            out.push(VerifyCase { name, model });
        }
    };
    for floor in [Floor::Roll, Floor::Slip, Floor::Fixed] {
        for contact in [Contact::Roll, Contact::Slip] {
            push(
                format!("{floor}-{contact}"),
                Ideal::new(unequal(), floor, contact, start("0.1", "0", "0")),
            );
        }
    }
    let mut bob = Params::identical_solid();
    bob.k2 = q("3/2");
    bob.r1 = q("1/2");
    push(
        "bobbin".into(),
        Ideal::new(bob, Floor::Roll, Contact::Roll, start("0.1", "0", "0")),
    );
    push(
        "moving-roll".into(),
        Ideal::new(
            unequal(),
            Floor::Roll,
            Contact::Roll,
            start("0.2", "0.3", "-0.7"),
        ),
    );
    push(
        "moving-slip".into(),
        Ideal::new(
            unequal(),
            Floor::Slip,
            Contact::Roll,
            start("0.2", "0.3", "-0.7"),
        ),
    );
    push(
        "paper-left".into(),
        Ideal::new(
            Params::identical_solid(),
            Floor::Roll,
            Contact::Roll,
            start("-0.05", "0", "0"),
        ),
    );
    out
}

/// One quantity computed by both routes.
#[derive(Debug, Clone)]
pub struct Comparison {
    /// Quantity (e.g. `theta_s`, `t=1.23 N12`).
    pub quantity: String,
    /// The first route's verified value.
    pub route1: Verified,
    /// The second route's verified value.
    pub route2: Verified,
    /// Leading significant digits on which the two values agree,
    /// ⌊−log10(|v2 − v1| / |v1|)⌋ (`None`: both print as 0 — exactly, or
    /// indistinguishable from 0 within their error bounds).
    pub agree: Option<u32>,
}

/// The comparison of one case.
#[derive(Debug, Clone)]
pub struct CaseReport {
    /// The case.
    pub case: VerifyCase,
    /// One row per quantity.
    pub rows: Vec<Comparison>,
    /// Route 2 at its higher precision: constraint drift, relative energy
    /// change, momentum change, steps, evaluations, largest column.
    pub run: TwoRun,
    /// Seconds spent in route 1 and route 2.
    pub seconds: (f64, f64),
}

/// Agreeing leading digits of `a` against `b` (capped at 999).
pub fn agreement(a: &Verified, b: &Verified) -> Option<u32> {
    let p = a.value.prec().max(b.value.prec());
    // both exactly 0, or both indistinguishable from 0 within their bounds
    if a.text == "0" && b.text == "0" {
        return None;
    }
    let d = Float::with_val(p, &a.value - &b.value).abs();
    if d.is_zero() {
        return Some(999);
    }
    if b.value.is_zero() {
        return Some(0);
    }
    let rel = Float::with_val(p, &d / Float::with_val(p, b.value.abs_ref()));
    let l = -rel.log10();
    let f = l.to_f64().floor();
    Some(if f < 0.0 { 0 } else { (f as u32).min(999) })
}

fn to_exact_time(x: f64) -> Result<Exact> {
    Exact::parse("time", &format!("{x:.3}"), false)
}

/// Runs both routes on `case` at `digits` digits and compares them.
///
/// Errors: either route failing to verify the digits.
pub fn compare_case(case: &VerifyCase, digits: u32) -> Result<CaseReport> {
    let model = &case.model;
    let clock = Instant::now();
    let mut oracle = Oracle::new(model, digits)?;
    let sep = oracle.separation()?;
    let t_s1 = sep
        .t_s
        .clone()
        .ok_or_else(|| Error::not_physical("the verification cases need a finite t_s"))?;
    let ts_f = t_s1.value.to_f64();
    let times: Vec<Exact> = [0.25, 0.6, 0.9]
        .iter()
        .map(|f| to_exact_time(ts_f * f))
        .collect::<Result<_>>()?;
    let rows1 = oracle.trajectory(&times)?;
    let sec1 = clock.elapsed().as_secs_f64();

    // the quantities of route 1, by name
    let mut r1: Vec<(String, Verified)> = vec![
        ("theta_s".into(), sep.theta_s.clone()),
        ("t_s".into(), t_s1.clone()),
    ];
    let extra_names = [
        "theta_N1_zero",
        "theta_phi1dot_zero",
        "theta_phi1_zero",
        "F21_at_s",
    ];
    for v in &sep.extra {
        if extra_names.contains(&v.name.as_str()) {
            r1.push((v.name.clone(), v.clone()));
        }
    }
    for (i, row) in rows1.iter().enumerate() {
        for (c, v) in row.iter().enumerate().skip(1) {
            r1.push((format!("t{}:{}", i + 1, TRAJECTORY_COLUMNS[c]), v.clone()));
        }
    }
    let names: Vec<&str> = r1.iter().map(|(n, _)| n.as_str()).collect();
    let want_phi = names
        .iter()
        .any(|n| *n == "theta_phi1dot_zero" || *n == "theta_phi1_zero");
    let floor = model.floor();
    let contact = model.contact();

    let clock = Instant::now();
    let mut last: Option<TwoRun> = None;
    let r2 = ladder(digits, &names, |p| {
        let tf: Vec<Float> = times.iter().map(|t| t.to_float(p)).collect();
        let t_end = Float::with_val(p, &t_s1.value) * 4u32 + 10u32;
        let run = two_cylinder(
            model,
            p,
            &tf,
            &t_end,
            &TwoOpts {
                phi1_events: want_phi,
                reach: Vec::new(),
            },
        )?;
        if run.rows.len() != tf.len() {
            return Err(Error::not_physical(
                "route 2 separated before a sample time of route 1",
            ));
        }
        let (sepst, serr) = run
            .separation
            .clone()
            .ok_or_else(|| Error::not_physical("route 2 found no separation"))?;
        let one = Float::with_val(p, 1u32);
        let ang = |s: &TwoState, e: &Float| -> Estimate {
            let err = Float::with_val(p, s.theta_dot.abs_ref()) * e;
            Estimate::new(s.theta.clone(), err, one.clone())
        };
        let pr = model.params();
        let fscale = Float::with_val(p, &Rational::from(&pr.m1 + &pr.m2)) * &pr.g;
        let tscale = Float::with_val(p, Float::with_val(p, &pr.r()) / &pr.g).sqrt();
        let mut out = Vec::with_capacity(names.len());
        for name in &names {
            let e = match *name {
                "theta_s" => ang(&sepst, &serr),
                "t_s" => Estimate::new(sepst.t.clone(), serr.clone(), tscale.clone()),
                "theta_N1_zero" | "theta_phi1dot_zero" | "theta_phi1_zero" => {
                    let hit = match *name {
                        "theta_N1_zero" => &run.n1_zero,
                        "theta_phi1dot_zero" => &run.phi1dot_zero,
                        _ => &run.phi1_zero,
                    };
                    match hit {
                        Some((s, e)) => ang(s, e),
                        None => {
                            return Err(Error::not_physical(format!("route 2 did not find {name}")))
                        }
                    }
                }
                "F21_at_s" => {
                    let err = Float::with_val(p, &fscale * &serr) / &tscale * 16u32;
                    Estimate::new(sepst.f21.clone(), err, fscale.clone())
                }
                _ => {
                    let (i, col) = name
                        .strip_prefix('t')
                        .and_then(|s| s.split_once(':'))
                        .and_then(|(i, c)| {
                            let i: usize = i.parse().ok()?;
                            let c = TRAJECTORY_COLUMNS.iter().position(|x| *x == c)?;
                            Some((i - 1, c))
                        })
                        .ok_or_else(|| Error::not_physical(format!("unknown quantity {name}")))?;
                    let v = run.rows[i].ideal_columns()[col].clone();
                    let exact_zero = (col == 9 && floor == Floor::Slip)
                        || (col == 11 && contact == Contact::Slip);
                    if exact_zero {
                        Estimate::zero(p, fscale.clone())
                    } else {
                        let scale = match col {
                            9..=12 => fscale.clone(),
                            2 => Float::with_val(p, &one / &tscale),
                            3 => Float::with_val(p, &one / &tscale) / &tscale,
                            6..=8 => Float::with_val(p, &pr.r()),
                            _ => one.clone(),
                        };
                        Estimate::rounded(v, scale)
                    }
                }
            };
            out.push(e);
        }
        last = Some(run);
        Ok(out)
    })?;
    let sec2 = clock.elapsed().as_secs_f64();
    let run = last.ok_or_else(|| Error::not_physical("route 2 did not run"))?;
    let rows = r1
        .into_iter()
        .zip(r2)
        .map(|((name, v1), v2)| Comparison {
            agree: agreement(&v2, &v1),
            quantity: name,
            route1: v1,
            route2: v2,
        })
        .collect();
    Ok(CaseReport {
        case: case.clone(),
        rows,
        run,
        seconds: (sec1, sec2),
    })
}

/// One compared quantity of [`VerifyReport`].
#[derive(Debug, Clone)]
pub struct VerifyRow {
    /// Quantity (e.g. `theta_s`, `t1 N12`, `event2_t`).
    pub quantity: String,
    /// Agreeing leading digits (`None`: both print as 0).
    pub agree: Option<u32>,
    /// The value printed (route 1, or the digits on which the integrators agree).
    pub value: String,
}

/// One case of [`VerifyReport`].
#[derive(Debug, Clone)]
pub struct VerifySection {
    /// `routes` (route 1 against route 2) or `friction` (the spectral route against GBS and collocation).
    pub kind: &'static str,
    /// Case name.
    pub name: String,
    /// The model (and friction laws) in words.
    pub description: String,
    /// The compared quantities.
    pub rows: Vec<VerifyRow>,
    /// Route 2's run statistics (routes sections).
    pub route2: Option<String>,
    /// Seconds spent in route 1 and route 2 (not part of the deterministic output).
    pub seconds: Option<(f64, f64)>,
}

/// What `cylroll verify` found: deterministic (timings apart, which only
/// [`VerifyReport::timings`] gives).
#[derive(Debug, Clone)]
pub struct VerifyReport {
    /// Significant digits requested from each route.
    pub digits: u32,
    /// The cases.
    pub sections: Vec<VerifySection>,
    /// One line per golden data file recomputed by route 2.
    pub golden: Vec<String>,
    /// The least agreement and where.
    pub worst: Option<(u32, String)>,
    /// Number of compared quantities.
    pub count: usize,
    /// Number of ideal-model cases.
    pub cases: usize,
}

impl VerifyReport {
    fn summary(&self) -> String {
        match &self.worst {
            Some((a, what)) => format!(
                "{} quantities in {} cases; the routes agree to at least {a} digits (least: {what})",
                self.count, self.cases
            ),
            None => "nothing compared".to_string(),
        }
    }

    /// The wall-clock time of each ideal case, one line each (for standard error).
    pub fn timings(&self) -> String {
        let mut s = String::new();
        for sec in &self.sections {
            if let Some((a, b)) = sec.seconds {
                s.push_str(&format!(
                    "{}: route 1 {a:.2} s, route 2 {b:.2} s\n",
                    sec.name
                ));
            }
        }
        s
    }

    /// The plain-text report.
    pub fn text(&self) -> String {
        let digits = self.digits;
        let mut out = String::new();
        out.push_str(
            "# cylroll verify: route 1 (Routh reduction + energy quadrature) against route 2\n",
        );
        out.push_str("# (time integration of the Lagrange-multiplier equations, appendix A.5, by GBS extrapolation)\n");
        out.push_str(&format!(
            "# {digits} significant digits requested from each route (each verified at two precisions);\n\
             # agree = leading significant digits on which the two routes' values agree, floor(-log10(|v2 - v1|/|v1|))\n\
             # (both values carry guard digits beyond the {digits} verified, so agree may exceed {digits}; 0=0: both print as 0);\n\
             # t1, t2, t3 are the sample times 0.25, 0.6, 0.9 t_s (rounded to 3 decimals)\n"
        ));
        let mut friction_header = false;
        for sec in &self.sections {
            if sec.kind == "friction" && !friction_header {
                friction_header = true;
                out.push_str(
                    "\n# Friction: the modes by Chebyshev spectral integration in the angle (the answers' route)\n\
                     # against two time integrators, GBS extrapolation and Gauss-Legendre collocation (an implicit\n\
                     # Runge-Kutta method), all at the higher working precision of the requested digits; the event\n\
                     # sequences must be identical; agree: the digits on which the spectral route meets both\n",
                );
            }
            out.push_str(&format!("\n## {}: {}\n", sec.name, sec.description));
            let w = if sec.kind == "friction" {
                16
            } else {
                sec.rows
                    .iter()
                    .map(|r| r.quantity.len())
                    .max()
                    .unwrap_or(8)
                    .max(8)
            };
            if sec.kind == "routes" {
                out.push_str(&format!(
                    "{:w$}  agree  value (route 1)\n",
                    "quantity",
                    w = w
                ));
            }
            for r in &sec.rows {
                let ag = match r.agree {
                    None => "0=0".to_string(),
                    Some(a) => a.to_string(),
                };
                out.push_str(&format!(
                    "{:w$}  {:>5}  {}\n",
                    r.quantity,
                    ag,
                    r.value,
                    w = w
                ));
            }
            if let Some(l) = &sec.route2 {
                out.push_str(&format!("route 2: {l}\n"));
            }
        }
        if !self.golden.is_empty() {
            out.push_str("\n## golden/data: every number recomputed by route 2 (at the file's digits + 40 bits)\n");
            for l in &self.golden {
                out.push_str(l);
                out.push('\n');
            }
        }
        out.push_str(&format!("\n# summary: {}\n", self.summary()));
        out
    }

    /// The report as one JSON object (numbers as decimal strings).
    pub fn json(&self) -> String {
        let sections: Vec<serde_json::Value> = self
            .sections
            .iter()
            .map(|s| {
                serde_json::json!({
                    "kind": s.kind,
                    "case": s.name,
                    "model": s.description,
                    "rows": s.rows.iter().map(|r| serde_json::json!({
                        "quantity": r.quantity,
                        "agree": r.agree.map(|a| a.to_string()),
                        "value": r.value,
                    })).collect::<Vec<_>>(),
                    "route2": s.route2,
                })
            })
            .collect();
        let v = serde_json::json!({
            "command": "verify",
            "digits_requested": self.digits.to_string(),
            "sections": sections,
            "golden": self.golden,
            "least_agreement": self.worst.as_ref().map(|w| w.0.to_string()),
            "least_agreement_at": self.worst.as_ref().map(|w| w.1.clone()),
            "summary": self.summary(),
        });
        serde_json::to_string_pretty(&v).unwrap_or_default() + "\n"
    }

    /// One CSV row per compared quantity.
    pub fn csv(&self) -> String {
        let mut out = String::from("kind,case,quantity,agree,value\n");
        for s in &self.sections {
            for r in &s.rows {
                out.push_str(&format!(
                    "{},{},{},{},{}\n",
                    s.kind,
                    s.name,
                    r.quantity,
                    r.agree.map_or("0=0".to_string(), |a| a.to_string()),
                    r.value
                ));
            }
        }
        out
    }
}

/// `cylroll verify --digits N`: both routes on [`cases`], the friction
/// integrators on their cases, and the golden data recomputed by route 2.
pub fn report(digits: u32) -> Result<VerifyReport> {
    crate::oracle::check_digits(digits)?;
    let mut sections = Vec::new();
    let mut worst: Option<(u32, String)> = None;
    let mut count = 0usize;
    let all = cases();
    for case in &all {
        let rep = compare_case(case, digits)?;
        let mut rows = Vec::new();
        for r in &rep.rows {
            count += 1;
            if let Some(a) = r.agree {
                if worst.as_ref().is_none_or(|(b, _)| a < *b) {
                    worst = Some((a, format!("{} {}", case.name, r.quantity)));
                }
            }
            rows.push(VerifyRow {
                quantity: r.quantity.clone(),
                agree: r.agree,
                value: r.route1.text.clone(),
            });
        }
        let st = &rep.run.run.stats;
        sections.push(VerifySection {
            kind: "routes",
            name: case.name.clone(),
            description: case.model.describe(),
            rows,
            route2: Some(format!(
                "constraint drift {} (of r, r/ts), energy change {}, momentum change {}; {} steps ({} rejected), {} evaluations, column <= {}",
                short(&rep.run.run.max_drift),
                short(&rep.run.energy_drift),
                short(&rep.run.momentum_drift),
                st.steps,
                st.rejected,
                st.evals,
                st.max_column,
            )),
            seconds: Some(rep.seconds),
        });
    }
    for (name, model) in super::routes::friction_cases() {
        let rows = super::routes::cross_check(&model, digits)?;
        let mut out = Vec::new();
        for r in &rows {
            let a = r.digits.floor().max(0.0) as u32;
            let value =
                if r.spectral.clone().abs() < Float::with_val(64, 10u32).pow(-(digits as i32)) {
                    "0".to_string()
                } else {
                    // only the digits on which the three integrators agree
                    crate::numeric::decimal::to_sig(&r.spectral, digits.min(a.max(1)))
                };
            count += 1;
            if worst.as_ref().is_none_or(|(b, _)| a < *b) {
                worst = Some((a, format!("{name} {}", r.name)));
            }
            out.push(VerifyRow {
                quantity: r.name.clone(),
                agree: Some(a),
                value,
            });
        }
        sections.push(VerifySection {
            kind: "friction",
            name: name.clone(),
            description: model.describe(),
            rows: out,
            route2: None,
            seconds: None,
        });
    }
    let golden = std::path::Path::new("golden/data");
    let mut golden_lines = Vec::new();
    if golden.is_dir() {
        // finish an interrupted update first: the set is whole or old, never mixed
        crate::golden::fileset::recover(golden)?;
        let mut files: Vec<_> = std::fs::read_dir(golden)
            .map_err(|e| Error::Io {
                path: golden.display().to_string(),
                what: e.to_string(),
            })?
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x == "json"))
            .collect();
        files.sort();
        for f in files {
            let text = std::fs::read_to_string(&f).map_err(|e| Error::Io {
                path: f.display().to_string(),
                what: e.to_string(),
            })?;
            let g = super::golden::check_golden(&text, 0)?;
            golden_lines.push(if g.checked == 0 {
                format!(
                    "{}: a friction case, computed by this route (held against an independent derivation in tests/friction.rs)",
                    g.case
                )
            } else if g.failures.is_empty() {
                let skipped = if g.skipped.is_empty() {
                    String::new()
                } else {
                    format!(
                        "; not reached by route 2: {}",
                        g.skipped
                            .iter()
                            .map(|(k, why)| format!("{k} ({why})"))
                            .collect::<Vec<_>>()
                            .join(", ")
                    )
                };
                format!(
                    "{}: all {} values round to the printed digits (largest |route 2 - golden| = {:.3} of a unit in the last printed digit){skipped}",
                    g.case, g.checked, g.worst_ulps
                )
            } else {
                format!(
                    "{}: {} of {} values DIFFER, e.g. {} golden {} route 2 {}",
                    g.case,
                    g.failures.len(),
                    g.checked,
                    g.failures[0].0,
                    g.failures[0].1,
                    g.failures[0].2
                )
            });
        }
    }
    Ok(VerifyReport {
        digits,
        sections,
        golden: golden_lines,
        worst,
        count,
        cases: all.len(),
    })
}
