//! Route 2 against the golden data (`golden/data/<case>.json`, schema
//! `cylroll-golden/2`): for an ideal model, every decimal string of the
//! closed branch — the scalars of separation and every cell of the grid
//! before it — is recomputed by time integration of the constrained
//! equations and must round to the printed digits. The free flight (closed
//! form) and the models with Coulomb friction (integrated by this route's
//! integrators already) are skipped.

use super::{two_cylinder, TwoOpts, TwoState};
use crate::error::{Error, Result};
use crate::exact::Exact;
use crate::model::input::{model_from_pairs, Pairs, FRICTION_KEYS, MODEL_KEYS};
use crate::motion::COLUMNS;
use crate::numeric::bits_for_digits;
use rug::ops::Pow;
use rug::{Float, Rational};

/// The outcome of checking one golden file.
#[derive(Debug, Clone)]
pub struct GoldenCheck {
    /// The case name of the file.
    pub case: String,
    /// Values compared (scalars and grid cells, the input times excluded).
    pub checked: usize,
    /// Values that did not round to the printed digits: (where, golden,
    /// route 2 to 40 digits).
    pub failures: Vec<(String, String, String)>,
    /// The smallest margin, in units of the last printed digit, by which a
    /// value stayed inside its half-unit (0.5 = exact agreement).
    pub worst_ulps: f64,
    /// Scalars this route cannot reach, with the reason (an angle past
    /// separation; the angle of an interior extremum, whose value is
    /// checked there but whose place is a root of a polynomial of route 1).
    pub skipped: Vec<(String, &'static str)>,
}

fn text(v: &serde_json::Value, what: &str) -> Result<String> {
    v.as_str()
        .map(|s| s.to_string())
        .ok_or_else(|| Error::invalid("golden", what, "expected a decimal string"))
}

/// Significant digits and the decimal exponent of the last digit of a
/// decimal string like `-0.0123400` (4 + 2 trailing zeros = 6 digits).
fn last_digit_exponent(s: &str) -> Option<(usize, i64)> {
    let s = s.trim_start_matches('-');
    let (mant, exp) = match s.find(['e', 'E']) {
        Some(i) => (&s[..i], s[i + 1..].parse::<i64>().ok()?),
        None => (s, 0),
    };
    let (int, frac) = mant.split_once('.').unwrap_or((mant, ""));
    let all = format!("{int}{frac}");
    let lead = all.len() - all.trim_start_matches('0').len();
    let sig = all.len().checked_sub(lead)?;
    Some((sig, exp - frac.len() as i64))
}

/// Checks route 2 against one golden JSON text, integrating at `prec` bits
/// (0: the file's digits plus 40 bits).
///
/// Errors: a malformed file; route 2 failing to run.
pub fn check_golden(json: &str, prec: u32) -> Result<GoldenCheck> {
    let d: serde_json::Value =
        serde_json::from_str(json).map_err(|e| Error::invalid("golden", "json", e.to_string()))?;
    let case = d["case"].as_str().unwrap_or("?").to_string();
    let mut pairs = Pairs::new();
    for k in MODEL_KEYS.iter().chain(&FRICTION_KEYS) {
        if let Some(v) = d["model"][k].as_str() {
            pairs.insert(k.to_string(), v.to_string());
        }
    }
    let Some(model) = model_from_pairs(&pairs)?.ideal() else {
        // integrated by this route's integrators already (the modes of
        // friction): nothing independent to recompute
        return Ok(GoldenCheck {
            case,
            checked: 0,
            failures: Vec::new(),
            worst_ulps: 0.0,
            skipped: vec![("every value".into(), "a model with Coulomb friction")],
        });
    };
    let digits: u32 = d["digits"]
        .as_str()
        .and_then(|s| s.parse().ok())
        .unwrap_or(30);
    let prec = if prec == 0 {
        bits_for_digits(digits) + 40
    } else {
        prec
    };
    let cols: Vec<String> = d["columns"]
        .as_array()
        .ok_or_else(|| Error::invalid("golden", "columns", "missing"))?
        .iter()
        .map(|c| text(c, "column"))
        .collect::<Result<_>>()?;
    let rows = d["rows"]
        .as_array()
        .ok_or_else(|| Error::invalid("golden", "rows", "missing"))?;
    // the rows of the closed branch (route 2 stops at separation)
    let mode_col = cols.iter().position(|c| c == "mode");
    let rows: Vec<&serde_json::Value> = rows
        .iter()
        .filter(|r| mode_col.is_none_or(|m| r[m].as_str() != Some("flight")))
        .collect();
    let mut times = Vec::with_capacity(rows.len());
    for r in &rows {
        let t = text(&r[0], "t")?;
        times.push(Exact::parse("t", &t, false)?.to_float(prec));
    }
    let scalars = d["scalars"]
        .as_object()
        .ok_or_else(|| Error::invalid("golden", "scalars", "missing"))?;
    let want_phi =
        scalars.contains_key("theta_phi1dot_zero") || scalars.contains_key("theta_phi1_zero");
    let t_end = match scalars.get("t_s").and_then(|v| v.as_str()) {
        Some(ts) => Exact::parse("t_s", ts, false)?.to_float(prec) * 2u32 + 10u32,
        None => Float::with_val(prec, 1000u32),
    };
    // extrema along the motion: at θs they are the separation state; inside
    // the motion, the state where θ reaches the golden angle
    let gold_of = |k: &str| scalars.get(k).and_then(|v| v.as_str()).map(String::from);
    let theta_s_text = gold_of("theta_s").unwrap_or_default();
    let mut reach = Vec::new();
    let mut reach_of = std::collections::HashMap::new();
    for k in ["theta_N1_min", "theta_mu_floor_max"] {
        if let Some(g) = gold_of(k) {
            if g != theta_s_text {
                reach_of.insert(k, reach.len());
                reach.push(Exact::parse(k, &g, false)?.to_float(prec));
            }
        }
    }
    let run = two_cylinder(
        &model,
        prec,
        &times,
        &t_end,
        &TwoOpts {
            phi1_events: want_phi,
            reach,
        },
    )?;
    let p = model.params();
    let fscale = Float::with_val(prec, &Rational::from(&p.m1 + &p.m2)) * &p.g;
    let tscale = Float::with_val(prec, Float::with_val(prec, &p.r()) / &p.g).sqrt();
    let ten = Float::with_val(prec, 10u32);
    let mut out = GoldenCheck {
        case,
        checked: 0,
        failures: Vec::new(),
        worst_ulps: 0.0,
        skipped: Vec::new(),
    };
    let judge = |out: &mut GoldenCheck, what: String, gold: &str, v: &Float, scale: &Float| {
        out.checked += 1;
        let ok = if gold == "0" {
            // printed as 0: exactly 0, or indistinguishable from 0 at the digits
            let tiny = Float::with_val(prec, scale / ten.clone().pow(digits));
            Float::with_val(prec, v.abs_ref()) <= tiny
        } else {
            match (Float::parse(gold), last_digit_exponent(gold)) {
                (Ok(g), Some((_, e))) => {
                    let g = Float::with_val(prec, g);
                    let ulp = ten.clone().pow(e as i32);
                    let d = Float::with_val(prec, v - &g).abs() / &ulp;
                    let r = d.to_f64();
                    if r > out.worst_ulps {
                        out.worst_ulps = r;
                    }
                    r <= 0.5 + 1e-6
                }
                _ => false,
            }
        };
        if !ok {
            out.failures
                .push((what, gold.to_string(), v.to_string_radix(10, Some(40))));
        }
    };
    let (sep, _) = run
        .separation
        .clone()
        .ok_or_else(|| Error::not_physical("route 2 found no separation"))?;
    let one = Float::with_val(prec, 1u32);
    let hit = |h: &Option<(TwoState, Float)>| h.as_ref().map(|x| x.0.theta.clone());
    // the state an extremum is at: separation, or the angle reached
    let extremum = |theta_key: &str| -> Option<TwoState> {
        match reach_of.get(theta_key) {
            None => Some(sep.clone()),
            Some(&i) => run.reached[i].clone(),
        }
    };
    let mu_floor = |st: &TwoState| Float::with_val(prec, st.f1.abs_ref()) / &st.n1;
    for (k, v) in scalars {
        let gold = text(v, k)?;
        if k.ends_with("_after_separation") {
            out.skipped
                .push((k.clone(), "past separation, where this route stops"));
            continue;
        }
        if reach_of.contains_key(k.as_str()) {
            out.skipped.push((
                k.clone(),
                "an interior extremum: its value is checked at this angle, its place is a root of route 1's polynomial",
            ));
            continue;
        }
        let (val, scale) = match k.as_str() {
            "theta_s" => (Some(sep.theta.clone()), one.clone()),
            "t_s" => (Some(sep.t.clone()), tscale.clone()),
            "F21_at_s" => (Some(sep.f21.clone()), fscale.clone()),
            "theta_N1_zero" => (hit(&run.n1_zero), one.clone()),
            "theta_phi1dot_zero" => (hit(&run.phi1dot_zero), one.clone()),
            "theta_phi1_zero" => (hit(&run.phi1_zero), one.clone()),
            "theta_N1_min" | "theta_mu_floor_max" => (Some(sep.theta.clone()), one.clone()),
            "work_s" => (Some(Float::new(prec)), one.clone()),
            "N1_min" => (extremum("theta_N1_min").map(|s| s.n1), fscale.clone()),
            "mu_floor_max" => (
                extremum("theta_mu_floor_max").map(|s| mu_floor(&s)),
                one.clone(),
            ),
            _ => (None, one.clone()),
        };
        let known = [
            "theta_s",
            "t_s",
            "F21_at_s",
            "theta_N1_zero",
            "theta_phi1dot_zero",
            "theta_phi1_zero",
            "theta_N1_min",
            "theta_mu_floor_max",
            "N1_min",
            "mu_floor_max",
            "work_s",
        ];
        if !known.contains(&k.as_str()) {
            out.skipped.push((
                k.clone(),
                "not on the closed branch (the branch point and the impact: closed forms of route 1)",
            ));
            continue;
        }
        match val {
            Some(x) => judge(&mut out, k.clone(), &gold, &x, &scale),
            None => out
                .failures
                .push((k.clone(), gold, "not found by route 2".into())),
        }
    }
    if run.rows.len() != rows.len() {
        return Err(Error::not_physical(format!(
            "route 2 reached {} of the {} grid times",
            run.rows.len(),
            rows.len()
        )));
    }
    let r1 = Float::with_val(prec, &p.r1);
    let r2 = Float::with_val(prec, &p.r2);
    let rr = Float::with_val(prec, &p.r());
    let vscale = Float::with_val(prec, &rr / &tscale);
    for (i, (r, st)) in rows.iter().zip(&run.rows).enumerate() {
        let mut vals: Vec<Float> = st.values().into_iter().cloned().collect();
        // the slip speeds and the work of an ideal model
        let psi2d = Float::with_val(prec, &st.phi2_dot - &st.theta_dot);
        let s1 = if model.floor() == crate::model::Floor::Slip {
            Float::with_val(prec, &st.x1_dot - Float::with_val(prec, &r1 * &st.phi1_dot))
        } else {
            Float::new(prec)
        };
        let s12 = if model.contact() == crate::model::Contact::Slip {
            Float::with_val(prec, &rr * &st.theta_dot) + Float::with_val(prec, &r2 * &psi2d)
                - Float::with_val(prec, &r1 * &st.phi1_dot)
        } else {
            Float::new(prec)
        };
        vals.extend([s1, s12, Float::new(prec)]);
        for (c, name) in cols.iter().enumerate().skip(1) {
            if name == "mode" {
                continue;
            }
            let j = COLUMNS
                .iter()
                .position(|x| x == name)
                .ok_or_else(|| Error::invalid("golden", name, "unknown column"))?;
            let gold = text(&r[c], name)?;
            let scale = match name.as_str() {
                "F1" | "N1" | "F21" | "N12" => fscale.clone(),
                "theta_dot" | "phi1_dot" | "phi2_dot" => Float::with_val(prec, &one / &tscale),
                "theta_ddot" => Float::with_val(prec, &one / &tscale) / &tscale,
                "x1" | "x2" | "y2" => rr.clone(),
                "x1_dot" | "x2_dot" | "y2_dot" | "s1" | "s12" => vscale.clone(),
                _ => one.clone(),
            };
            judge(&mut out, format!("row {i} {name}"), &gold, &vals[j], &scale);
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::last_digit_exponent;

    #[test]
    fn digit_positions() {
        assert_eq!(last_digit_exponent("1.05127"), Some((6, -5)));
        assert_eq!(last_digit_exponent("-0.00123400"), Some((6, -8)));
        assert_eq!(last_digit_exponent("6.36"), Some((3, -2)));
        assert_eq!(last_digit_exponent("1.5e-40"), Some((2, -41)));
    }
}
