//! `cylroll check`: hold another program's CSV against the oracle.
//!
//! The candidate's columns are matched by header (any subset of the golden
//! columns; `t` is required); the oracle is evaluated at the candidate's own
//! times (no interpolation of either side). A value fails when
//! |candidate − oracle| > atol + rtol·|oracle| (numpy's `isclose` rule).

use super::Case;
use crate::error::{Error, Result};
use crate::exact::Exact;
use crate::numeric::decimal::short;
use crate::oracle::{Oracle, TRAJECTORY_COLUMNS};
use rug::Float;
use serde_json::{json, Value};

/// One candidate cell: (column index, its text, its value).
type Cell = (usize, String, f64);

/// Per-column statistics.
#[derive(Debug, Clone)]
pub struct ColumnStats {
    /// Column name.
    pub name: String,
    /// Largest absolute error.
    pub max_abs: f64,
    /// Time where it occurs.
    pub max_abs_t: String,
    /// Largest relative error (|err|/|oracle|; oracle values that are 0 skip it).
    pub max_rel: f64,
    /// Time where it occurs.
    pub max_rel_t: String,
    /// Rows exceeding the tolerance.
    pub failures: usize,
}

/// The first value out of tolerance.
#[derive(Debug, Clone)]
pub struct FirstFailure {
    /// 1-based data row of the candidate file.
    pub row: usize,
    /// Its time.
    pub t: String,
    /// The column.
    pub column: String,
    /// The candidate's value as written.
    pub candidate: String,
    /// The oracle's value (verified digits).
    pub oracle: String,
}

/// The verdict on a candidate file.
#[derive(Debug, Clone)]
pub struct CheckReport {
    /// The case checked against.
    pub case: String,
    /// Relative tolerance.
    pub rtol: f64,
    /// Absolute tolerance.
    pub atol: f64,
    /// Data rows read.
    pub rows: usize,
    /// Column statistics in the candidate's column order (without `t`).
    pub columns: Vec<ColumnStats>,
    /// The first failing value, if any.
    pub first_failure: Option<FirstFailure>,
    /// Significant digits of the oracle values used.
    pub digits: u32,
}

impl CheckReport {
    /// Whether every value is within tolerance.
    pub fn passed(&self) -> bool {
        self.first_failure.is_none()
    }

    /// A plain-text table.
    pub fn text(&self) -> String {
        let mut s = format!(
            "# cylroll check against case {} ({} rows; oracle at {} digits; fail if |err| > {:e} + {:e}*|oracle|)\n",
            self.case, self.rows, self.digits, self.atol, self.rtol
        );
        s.push_str(&format!(
            "{:<11} {:>10} {:>12} {:>10} {:>12} {:>9}\n",
            "column", "max_abs", "at_t", "max_rel", "at_t", "failures"
        ));
        for c in &self.columns {
            s.push_str(&format!(
                "{:<11} {:>10.3e} {:>12} {:>10.3e} {:>12} {:>9}\n",
                c.name, c.max_abs, c.max_abs_t, c.max_rel, c.max_rel_t, c.failures
            ));
        }
        match &self.first_failure {
            None => s.push_str("PASS: every value within tolerance\n"),
            Some(f) => s.push_str(&format!(
                "FAIL: first at row {} (t = {}), column {}: candidate {} vs oracle {}\n",
                f.row, f.t, f.column, f.candidate, f.oracle
            )),
        }
        s
    }

    /// A JSON object (numbers as decimal strings).
    pub fn json(&self) -> String {
        let cols: Vec<Value> = self
            .columns
            .iter()
            .map(|c| {
                json!({
                    "column": c.name,
                    "max_abs": format!("{:.3e}", c.max_abs),
                    "max_abs_t": c.max_abs_t,
                    "max_rel": format!("{:.3e}", c.max_rel),
                    "max_rel_t": c.max_rel_t,
                    "failures": c.failures.to_string(),
                })
            })
            .collect();
        let first = self.first_failure.as_ref().map(|f| {
            json!({"row": f.row.to_string(), "t": f.t, "column": f.column, "candidate": f.candidate, "oracle": f.oracle})
        });
        let v = json!({
            "case": self.case,
            "passed": self.passed(),
            "rows": self.rows.to_string(),
            "rtol": format!("{:e}", self.rtol),
            "atol": format!("{:e}", self.atol),
            "oracle_digits": self.digits.to_string(),
            "columns": cols,
            "first_failure": first,
        });
        serde_json::to_string_pretty(&v).unwrap_or_default() + "\n"
    }
}

/// Checks the CSV text `csv` (read from `source`, for messages) against `case`.
pub fn check(
    csv: &str,
    source: &str,
    case: &Case,
    rtol: f64,
    atol: f64,
    digits: u32,
) -> Result<CheckReport> {
    for (name, v) in [("rtol", rtol), ("atol", atol)] {
        if !v.is_finite() || v < 0.0 {
            return Err(Error::invalid(name, v, "must be a finite number >= 0"));
        }
    }
    let mut lines = csv.lines().filter(|l| !l.trim().is_empty());
    let header = lines
        .next()
        .ok_or_else(|| Error::invalid("candidate", source, "is empty; expected a header row"))?;
    let cols: Vec<String> = header
        .split(',')
        .map(|c| c.trim().trim_matches('"').to_string())
        .collect();
    let known: Vec<&str> = if case.friction.is_some() {
        crate::friction::columns()
    } else {
        TRAJECTORY_COLUMNS.to_vec()
    };
    let mut idx = Vec::new();
    for c in &cols {
        match known.iter().position(|g| g == c) {
            Some(i) => idx.push(i),
            None => {
                return Err(Error::invalid(
                    "candidate",
                    source,
                    format!("unknown column {c:?}; allowed: {}", known.join(", ")),
                ))
            }
        }
    }
    let t_col = cols
        .iter()
        .position(|c| c == "t")
        .ok_or_else(|| Error::invalid("candidate", source, "needs a column named t"))?;
    let mut data: Vec<(Exact, Vec<Cell>)> = Vec::new();
    for (row, line) in lines.enumerate() {
        let cells: Vec<&str> = line.split(',').map(|c| c.trim()).collect();
        if cells.len() != cols.len() {
            return Err(Error::invalid(
                "candidate",
                source,
                format!(
                    "row {} has {} fields, the header {}",
                    row + 1,
                    cells.len(),
                    cols.len()
                ),
            ));
        }
        let t = Exact::parse("t", cells[t_col], false).map_err(|_| {
            Error::invalid(
                "candidate",
                source,
                format!("row {}: t = {:?} is not a number", row + 1, cells[t_col]),
            )
        })?;
        let mut vals = Vec::new();
        for (k, cell) in cells.iter().enumerate() {
            if k == t_col {
                continue;
            }
            let v: f64 = cell.parse().map_err(|_| {
                Error::invalid(
                    "candidate",
                    source,
                    format!(
                        "row {}, column {}: {:?} is not a number",
                        row + 1,
                        cols[k],
                        cell
                    ),
                )
            })?;
            if !v.is_finite() {
                return Err(Error::invalid(
                    "candidate",
                    source,
                    format!("row {}, column {}: {cell} is not finite", row + 1, cols[k]),
                ));
            }
            vals.push((idx[k], cell.to_string(), v));
        }
        data.push((t, vals));
    }
    if data.is_empty() {
        return Err(Error::invalid("candidate", source, "has no data rows"));
    }
    let times: Vec<Exact> = data.iter().map(|d| d.0.clone()).collect();
    let rows = match &case.friction {
        Some(fr) => crate::friction::answer::trajectory(&case.model, fr, digits, &times)?.rows,
        None => Oracle::new(&case.model, digits)?.trajectory(&times)?,
    };
    let mut stats: Vec<ColumnStats> = cols
        .iter()
        .filter(|c| c.as_str() != "t")
        .map(|c| ColumnStats {
            name: c.clone(),
            max_abs: 0.0,
            max_abs_t: "-".into(),
            max_rel: 0.0,
            max_rel_t: "-".into(),
            failures: 0,
        })
        .collect();
    let mut first = None;
    let p = 128;
    for (r, ((t, vals), orow)) in data.iter().zip(&rows).enumerate() {
        for (j, (gi, text, _)) in vals.iter().enumerate() {
            let o = &orow[*gi];
            let cand = Exact::parse("value", text, false)?.to_float(p);
            // a value printed as 0 is 0 to the verified accuracy: compare
            // with 0 (and no relative error), not with its unverified digits
            let ov = if o.digits == 0 && o.text == "0" {
                Float::new(p)
            } else {
                Float::with_val(p, &o.value)
            };
            let err = Float::with_val(p, &cand - &ov).abs();
            let mag = Float::with_val(p, ov.abs_ref());
            let abs = err.to_f64();
            let rel = if mag.is_zero() {
                0.0
            } else {
                Float::with_val(p, &err / &mag).to_f64()
            };
            let st = &mut stats[j];
            if abs > st.max_abs || st.max_abs_t == "-" {
                st.max_abs = abs;
                st.max_abs_t = t.to_string();
            }
            if rel > st.max_rel || st.max_rel_t == "-" {
                st.max_rel = rel;
                st.max_rel_t = t.to_string();
            }
            let limit = Float::with_val(p, &mag * rtol) + atol;
            if err > limit {
                st.failures += 1;
                if first.is_none() {
                    first = Some(FirstFailure {
                        row: r + 1,
                        t: t.to_string(),
                        column: st.name.clone(),
                        candidate: text.clone(),
                        oracle: o.text.clone(),
                    });
                }
            }
        }
    }
    let _ = short;
    Ok(CheckReport {
        case: case.name.clone(),
        rtol,
        atol,
        rows: data.len(),
        columns: stats,
        first_failure: first,
        digits,
    })
}
