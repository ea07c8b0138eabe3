//! Every CSV of the report in one tidy ASCII schema:
//!
//! `case,point,phase,quantity,unit,value,digits`
//!
//! one value per row: `case` names the curve or table row (`key=value`
//! pairs joined by `;`), `point` numbers the samples of a curve (empty for
//! a table's value), `phase` is the motion's phase there (`stick/slip+`,
//! `flight`; empty where it does not apply), `quantity` and `unit` are
//! ASCII names (`theta`, `rad`; `t`, `tau` = sqrt(r1/g); forces in `m1*g`),
//! `value` a decimal and `digits` its verified significant digits (`exact`
//! for an input such as a requested time, `15` for a closed form evaluated
//! in double precision, `interpolated` for a contour between verified
//! nodes).

use super::model::{ascii_key, Figure};
use std::fmt::Write as _;

/// The header of every CSV.
pub const HEADER: &str = "case,point,phase,quantity,unit,value,digits";

/// One value.
#[derive(Debug, Clone, PartialEq)]
pub struct Record {
    /// The curve or row.
    pub case: String,
    /// Sample number (None: a table's value).
    pub point: Option<usize>,
    /// Phase (empty: none).
    pub phase: String,
    /// Quantity (ASCII).
    pub quantity: String,
    /// Unit (ASCII).
    pub unit: String,
    /// The value as text.
    pub value: String,
    /// Digits.
    pub digits: String,
}

/// A value with `sig` significant digits, plain ASCII.
pub fn num(v: f64, sig: usize) -> String {
    if !v.is_finite() {
        return String::new();
    }
    if v == 0.0 {
        return "0".into();
    }
    let e = v.abs().log10().floor() as i32;
    if !(-6..=9).contains(&e) {
        return format!("{:.*e}", sig.saturating_sub(1), v);
    }
    let dec = (sig as i32 - 1 - e).max(0) as usize;
    let s = format!("{v:.dec$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

fn field(s: &str) -> String {
    let s: String = s.chars().filter(|c| c.is_ascii() && *c != '\n').collect();
    if s.contains(',') || s.contains('"') {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s
    }
}

/// The CSV text of records.
pub fn write(records: &[Record]) -> String {
    let mut s = String::from(HEADER);
    s.push('\n');
    for r in records {
        let _ = writeln!(
            s,
            "{},{},{},{},{},{},{}",
            field(&r.case),
            r.point.map_or(String::new(), |p| p.to_string()),
            field(&r.phase),
            field(&r.quantity),
            field(&r.unit),
            field(&r.value),
            field(&r.digits)
        );
    }
    s
}

/// A record of a verified value.
pub fn verified(
    case: &str,
    quantity: &str,
    unit: &str,
    v: &crate::numeric::verify::Verified,
) -> Record {
    Record {
        case: case.into(),
        point: None,
        phase: String::new(),
        quantity: quantity.into(),
        unit: unit.into(),
        value: v.text.clone(),
        digits: v.digits.to_string(),
    }
}

/// The data of a figure: every drawn or listed point of every curve (its x
/// and its y), every marker and every reference line.
pub fn figure(fig: &Figure) -> String {
    let mut out = Vec::new();
    for (k, p) in fig.panels.iter().enumerate() {
        let panel = if p.title.is_empty() {
            format!("panel={}", k + 1)
        } else {
            format!("panel={}", ascii_key(&p.title))
        };
        for s in &p.series {
            let case = format!("{panel};{}", s.key);
            let yq = s.yq.as_ref().unwrap_or(&p.yq);
            let mut i = 0;
            for (j, &(x, y)) in s.points.iter().enumerate() {
                if !(x.is_finite() && y.is_finite()) {
                    continue;
                }
                let phase = s.phases.get(j).cloned().unwrap_or_default();
                for (q, v, d) in [(&p.xq, x, s.digits.0), (yq, y, s.digits.1)] {
                    out.push(Record {
                        case: case.clone(),
                        point: Some(i),
                        phase: phase.clone(),
                        quantity: q.name.clone(),
                        unit: q.unit.clone(),
                        value: num(v, d.sig()),
                        digits: d.text(),
                    });
                }
                i += 1;
            }
        }
        for m in &p.markers {
            let key = if m.key.is_empty() {
                ascii_key(&m.title)
            } else {
                m.key.clone()
            };
            let case = format!("{panel};marker={key}");
            for (q, v) in [(&p.xq, m.at.0), (&p.yq, m.at.1)] {
                out.push(Record {
                    case: case.clone(),
                    point: None,
                    phase: String::new(),
                    quantity: q.name.clone(),
                    unit: q.unit.clone(),
                    value: num(v, m.digits.sig()),
                    digits: m.digits.text(),
                });
            }
        }
        for l in &p.lines {
            let q = if l.vertical { &p.xq } else { &p.yq };
            out.push(Record {
                case: format!(
                    "{panel};line={}",
                    if l.key.is_empty() {
                        ascii_key(&l.title)
                    } else {
                        l.key.clone()
                    }
                ),
                point: None,
                phase: String::new(),
                quantity: q.name.clone(),
                unit: q.unit.clone(),
                value: num(l.at, l.digits.sig()),
                digits: l.digits.text(),
            });
        }
    }
    let mut s = write(&out);
    for extra in &fig.extra_csv {
        s.push_str(extra);
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_and_fields_are_plain_ascii() {
        assert_eq!(num(0.000_123_456_789, 4), "0.0001235");
        assert_eq!(num(-2.5, 12), "-2.5");
        assert_eq!(field("θ a,b"), "\" a,b\"");
    }
}
