//! Every table's numbers as tidy records ([`super::csv`]): the row's case,
//! the quantity and unit of the column, the value exactly as printed and
//! its significant digits (a table prints exactly the digits verified).

use super::csv::Record;
use super::data::{FORCE_ANGLES, PLANE_TABLE_RATIOS};
use super::page::Table;

/// Significant digits of a decimal text (`1.0472`, `-0.0031`, `2.5e-7`).
pub fn sig_digits(s: &str) -> usize {
    let m = s.split(['e', 'E']).next().unwrap_or("");
    let digits: String = m.chars().filter(|c| c.is_ascii_digit()).collect();
    digits.trim_start_matches('0').len().max(usize::from(
        digits.chars().all(|c| c == '0') && !digits.is_empty(),
    ))
}

/// A model's row name (`floor roll, contact slip`) as a case.
fn model_case(name: &str) -> String {
    name.replace("floor ", "floor=")
        .replace(", contact ", ";contact=")
}

fn ascii(s: &str) -> String {
    super::model::ascii_key(s)
}

/// The records of a table (empty: a table without numbers of its own).
pub fn table_records(t: &Table) -> Vec<Record> {
    let mut out = Vec::new();
    for row in &t.rows {
        let cell = |c: usize| {
            row.get(c)
                .and_then(|x| x.strip_prefix('='))
                .map(str::to_string)
        };
        let cols: Vec<(usize, String, &str, &str)> = match t.id.as_str() {
            "separation-top" => vec![
                (2, model_case(&row[0]) + ";theta0=0", "theta_s", "rad"),
                (
                    3,
                    model_case(&row[0]) + ";theta0=0",
                    "theta_s_rounded",
                    "deg",
                ),
                (
                    5,
                    model_case(&row[0]) + ";theta0=0",
                    "theta_s_closed_form",
                    "rad",
                ),
                (7, model_case(&row[0]) + ";theta0=0", "F21_at_s", "m1*g"),
            ],
            "separation-start" => {
                let case = format!(
                    "{};theta0={}",
                    model_case(&row[0]),
                    cell(1).unwrap_or_default()
                );
                vec![
                    (2, case.clone(), "theta_s", "rad"),
                    (3, case.clone(), "t_s", "tau"),
                    (5, case, "theta_s_closed_form", "rad"),
                ]
            }
            "forces" => {
                const Q: [(&str, &str); 8] = [
                    ("F1", "m1*g"),
                    ("N1", "m1*g"),
                    ("F21", "m1*g"),
                    ("N12", "m1*g"),
                    ("theta_dot", "rad/tau"),
                    ("theta_ddot", "rad/tau^2"),
                    ("mu_floor", "1"),
                    ("mu_contact", "1"),
                ];
                let qi = t.rows.iter().position(|r| r == row).unwrap_or(0);
                let (q, u) = Q.get(qi).copied().unwrap_or(("value", ""));
                FORCE_ANGLES
                    .iter()
                    .enumerate()
                    .map(|(i, a)| {
                        (
                            i + 1,
                            format!("floor=roll;contact=roll;theta0=0;theta={a}"),
                            q,
                            u,
                        )
                    })
                    .collect()
            }
            "friction" => {
                let case = format!(
                    "floor=roll;contact=roll;theta0=0;mu={}",
                    cell(0).unwrap_or_default()
                );
                vec![
                    (1, case.clone(), "theta_slip_floor", "rad"),
                    (2, case.clone(), "theta_slip_contact", "rad"),
                    (4, case, "theta_s", "rad"),
                ]
            }
            "plane-points" => {
                let k2 = cell(0).unwrap_or_default();
                PLANE_TABLE_RATIOS
                    .iter()
                    .enumerate()
                    .map(|(i, r)| {
                        (
                            i + 1,
                            format!("floor=roll;contact=roll;m2_over_m1={r};k2={k2}"),
                            "theta_s",
                            "rad",
                        )
                    })
                    .collect()
            }
            "plane-fixed" => {
                let case = format!(
                    "floor=fixed;contact=roll;k2={}",
                    cell(0).unwrap_or_default()
                );
                vec![
                    (1, case.clone(), "theta_s", "rad"),
                    (2, case, "theta_s_closed_form", "rad"),
                ]
            }
            "friction-events" => {
                let case = format!(
                    "mu={};event={};contact={}",
                    cell(0).unwrap_or_default(),
                    ascii(&row[1]),
                    ascii(&row[2])
                );
                vec![(3, case.clone(), "t", "tau"), (4, case, "theta", "rad")]
            }
            _ => Vec::new(),
        };
        for (c, case, q, u) in cols {
            if let Some(v) = cell(c) {
                if v.parse::<f64>().is_err() {
                    continue;
                }
                out.push(Record {
                    case,
                    point: None,
                    phase: String::new(),
                    quantity: q.into(),
                    unit: u.into(),
                    digits: sig_digits(&v).to_string(),
                    value: v,
                });
            }
        }
    }
    out
}

/// `plane.csv`: every point of the parameter plane computed.
pub fn plane_records(
    plane: &std::collections::BTreeMap<
        super::data::PlaneKey,
        crate::error::Result<crate::numeric::verify::Verified>,
    >,
) -> Vec<Record> {
    plane
        .iter()
        .filter_map(|(k, v)| {
            let v = v.as_ref().ok()?;
            let floor = match k.floor {
                super::data::FloorKey::Roll => "roll",
                super::data::FloorKey::Fixed => "fixed",
            };
            Some(super::csv::verified(
                &format!(
                    "floor={floor};contact=roll;m2_over_m1={};k2={};k1=1/2",
                    k.ratio, k.k2
                ),
                "theta_s",
                "rad",
                v,
            ))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn significant_digits() {
        assert_eq!(sig_digits("1.0471975511965977"), 17);
        assert_eq!(sig_digits("-0.00310"), 3);
        assert_eq!(sig_digits("2.5e-7"), 2);
        assert_eq!(sig_digits("0"), 1);
    }
}
