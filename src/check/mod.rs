//! `cylroll check`: hold another program's CSV against the oracle.
//!
//! The candidate's columns are matched by header (any subset of the golden
//! columns; `t` is required); the oracle is evaluated at the candidate's own
//! times (no interpolation of either side). A value fails when
//! |candidate − oracle| > atol + rtol·|oracle| (numpy's `isclose` rule).

use crate::error::{Error, Result};
use crate::exact::Exact;
use crate::golden::Case;
use crate::oracle::{Options, Row};
use rug::Float;
use serde_json::{json, Value};
use std::io::{BufRead, Read};

/// One candidate cell: (golden column index, its text, its value; NaN for
/// the `mode` column's text).
type Cell = (usize, String, f64);

/// The columns a candidate may have: every trajectory column and `mode`.
fn known_columns() -> Vec<&'static str> {
    let mut k = crate::motion::COLUMNS.to_vec();
    k.push("mode");
    k
}

/// The index of the `mode` column in [`known_columns`].
const MODE: usize = crate::motion::COLUMNS.len();

/// The full column lists of the first golden schema: a candidate whose
/// header is exactly one of them is read as schema 1 (φ2 of a rolling
/// contact in the paper's gauge, r1 θ0/r2 below today's).
const V1_HEADERS: [&str; 2] = [
    "t,theta,theta_dot,theta_ddot,phi1,phi2,x1,x2,y2,F1,N1,F21,N12",
    "t,theta,theta_dot,theta_ddot,phi1,phi2,x1,x2,y2,F1,N1,F21,N12,s1,s12,work,mode",
];

/// Rows evaluated by the oracle at once: memory stays bounded by this many
/// rows whatever the candidate's length.
pub const CHUNK_ROWS: usize = 4096;

/// Longest line of a candidate, in bytes.
pub const MAX_LINE_BYTES: u64 = 1 << 16;

/// Default largest number of data rows.
pub const DEFAULT_MAX_ROWS: usize = 1_000_000;

/// Per-column statistics.
#[derive(Debug, Clone)]
pub struct ColumnStats {
    /// Column name.
    pub name: String,
    /// Largest absolute error.
    pub max_abs: f64,
    /// Time where it occurs.
    pub max_abs_t: String,
    /// Largest relative error |err|/|oracle| (`None` when every oracle value
    /// of the column is 0, where a relative error is undefined).
    pub max_rel: Option<f64>,
    /// Time where it occurs.
    pub max_rel_t: String,
    /// Largest |err| / (atol + rtol·|oracle|): above 1 fails.
    pub worst_ratio: f64,
    /// Which term of the limit was the larger where `worst_ratio` occurs:
    /// `"atol"` (an oracle value near 0) or `"rtol"`.
    pub worst_bound: &'static str,
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
    /// The limit atol + rtol·|oracle| it exceeded.
    pub limit: f64,
    /// Which term of the limit was the larger (`"atol"` or `"rtol"`).
    pub bound: &'static str,
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
            "{:<11} {:>10} {:>12} {:>10} {:>12} {:>10} {:>5} {:>9}\n",
            "column", "max_abs", "at_t", "max_rel", "at_t", "err/limit", "bound", "failures"
        ));
        for c in &self.columns {
            s.push_str(&format!(
                "{:<11} {:>10.3e} {:>12} {:>10} {:>12} {:>10.3e} {:>5} {:>9}\n",
                c.name,
                c.max_abs,
                c.max_abs_t,
                rel_text(c.max_rel),
                c.max_rel_t,
                c.worst_ratio,
                c.worst_bound,
                c.failures
            ));
        }
        match &self.first_failure {
            None => s.push_str("PASS: every value within tolerance\n"),
            Some(f) => s.push_str(&format!(
                "FAIL: first at row {} (t = {}), column {}: candidate {} vs oracle {}; |err| > {:.3e} ({} decides)\n",
                f.row, f.t, f.column, f.candidate, f.oracle, f.limit, f.bound
            )),
        }
        s
    }

    /// One CSV row per compared column, then a `result` row.
    pub fn csv(&self) -> String {
        let mut s = String::from(
            "column,max_abs,max_abs_t,max_rel,max_rel_t,worst_err_over_limit,worst_bound,failures\n",
        );
        for c in &self.columns {
            s.push_str(&format!(
                "{},{:.3e},{},{},{},{:.3e},{},{}\n",
                c.name,
                c.max_abs,
                c.max_abs_t,
                rel_text(c.max_rel),
                c.max_rel_t,
                c.worst_ratio,
                c.worst_bound,
                c.failures
            ));
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
                    "max_rel": c.max_rel.map(|r| format!("{r:.3e}")),
                    "max_rel_t": c.max_rel_t,
                    "worst_err_over_limit": format!("{:.3e}", c.worst_ratio),
                    "worst_bound": c.worst_bound,
                    "failures": c.failures.to_string(),
                })
            })
            .collect();
        let first = self.first_failure.as_ref().map(|f| {
            json!({"row": f.row.to_string(), "t": f.t, "column": f.column, "candidate": f.candidate,
                   "oracle": f.oracle, "limit": format!("{:.3e}", f.limit), "bound": f.bound})
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

/// `max_rel` as text: `-` where undefined.
fn rel_text(r: Option<f64>) -> String {
    r.map_or("-".into(), |r| format!("{r:.3e}"))
}

/// Checks the CSV text `csv` (read from `source`, for messages) against `case`
/// ([`check_reader`] with the default row limit).
pub fn check(
    csv: &str,
    source: &str,
    case: &Case,
    rtol: f64,
    atol: f64,
    digits: u32,
) -> Result<CheckReport> {
    let lim = Limits {
        rtol,
        atol,
        digits,
        max_rows: DEFAULT_MAX_ROWS,
        schema: None,
    };
    check_reader(std::io::Cursor::new(csv.as_bytes()), source, case, &lim)
}

/// The tolerances and limits of a check.
#[derive(Debug, Clone, Copy)]
pub struct Limits {
    /// Relative tolerance.
    pub rtol: f64,
    /// Absolute tolerance.
    pub atol: f64,
    /// Significant digits of the oracle values.
    pub digits: u32,
    /// Largest number of data rows accepted.
    pub max_rows: usize,
    /// The candidate's schema: 1 (φ2 in the paper's gauge), 2, or `None`
    /// (2, unless the header is exactly a full schema-1 column list).
    pub schema: Option<u32>,
}

/// Reads one line of at most [`MAX_LINE_BYTES`] (without its line end);
/// `None` at the end of the input.
fn next_line<R: BufRead>(r: &mut R, buf: &mut Vec<u8>, source: &str) -> Result<Option<String>> {
    buf.clear();
    let n = r
        .by_ref()
        .take(MAX_LINE_BYTES + 1)
        .read_until(b'\n', buf)
        .map_err(|e| Error::invalid("candidate", source, format!("cannot be read: {e}")))?;
    if n == 0 {
        return Ok(None);
    }
    if buf.len() as u64 > MAX_LINE_BYTES {
        return Err(Error::invalid(
            "candidate",
            source,
            format!("has a line longer than {MAX_LINE_BYTES} bytes"),
        ));
    }
    let text = std::str::from_utf8(buf)
        .map_err(|_| Error::invalid("candidate", source, "is not UTF-8 text"))?;
    Ok(Some(text.trim_end_matches(['\n', '\r']).to_string()))
}

/// Checks the CSV read from `reader` (named `source` in messages) against
/// `case`, in chunks of [`CHUNK_ROWS`] rows: memory does not grow with the
/// number of rows.
///
/// Errors: a malformed candidate (header, fields, numbers), more rows than
/// `lim.max_rows`, nothing to compare, times the oracle refuses.
pub fn check_reader<R: BufRead>(
    mut reader: R,
    source: &str,
    case: &Case,
    lim: &Limits,
) -> Result<CheckReport> {
    let (rtol, atol, digits) = (lim.rtol, lim.atol, lim.digits);
    for (name, v) in [("rtol", rtol), ("atol", atol)] {
        if !v.is_finite() || v < 0.0 {
            return Err(Error::invalid(name, v, "must be a finite number >= 0"));
        }
    }
    let mut buf = Vec::new();
    let header = loop {
        match next_line(&mut reader, &mut buf, source)? {
            None => {
                return Err(Error::invalid(
                    "candidate",
                    source,
                    "is empty; expected a header row",
                ))
            }
            Some(l) if l.trim().is_empty() => continue,
            Some(l) => break crate::model::input::strip_bom(&l).to_string(),
        }
    };
    let cols: Vec<String> = header
        .split(',')
        .map(|c| c.trim().trim_matches('"').to_string())
        .collect();
    let known = known_columns();
    let schema1 = lim.schema == Some(1)
        || (lim.schema.is_none() && V1_HEADERS.contains(&cols.join(",").as_str()));
    // φ2 of schema 1: the paper's gauge for a contact that starts rolling
    let phi2_shift = if schema1 && *case.model.contact() != crate::model::Law::Frictionless {
        let pr = case.model.params();
        let th0 = case.model.start().theta0.to_float(256);
        Float::with_val(256, &pr.r1) * th0 / Float::with_val(256, &pr.r2)
    } else {
        Float::new(256)
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
    if cols.len() < 2 {
        return Err(Error::invalid(
            "candidate",
            source,
            format!(
                "has only the column t: nothing to compare (add any of {})",
                known[1..].join(", ")
            ),
        ));
    }
    let mut stats: Vec<ColumnStats> = cols
        .iter()
        .filter(|c| c.as_str() != "t")
        .map(|c| ColumnStats {
            name: c.clone(),
            max_abs: 0.0,
            max_abs_t: "-".into(),
            max_rel: None,
            max_rel_t: "-".into(),
            worst_ratio: 0.0,
            worst_bound: "-",
            failures: 0,
        })
        .collect();
    let mut first = None;
    let mut rows = 0usize;
    let mut chunk: Vec<(Exact, Vec<Cell>)> = Vec::with_capacity(CHUNK_ROWS);
    loop {
        let line = next_line(&mut reader, &mut buf, source)?;
        let done = line.is_none();
        if let Some(line) = line {
            if line.trim().is_empty() {
                continue;
            }
            rows += 1;
            if rows > lim.max_rows {
                return Err(Error::invalid(
                    "candidate",
                    source,
                    format!(
                        "has more than {} data rows (raise --max-rows, at most 100000000)",
                        lim.max_rows
                    ),
                ));
            }
            chunk.push(parse_row(&line, rows, &cols, &idx, t_col, source)?);
        }
        if chunk.len() == CHUNK_ROWS || (done && !chunk.is_empty()) {
            let times: Vec<Exact> = chunk.iter().map(|d| d.0.clone()).collect();
            let orows =
                crate::oracle::trajectory(&case.model, &times, &Options::digits(digits))?.rows;
            let row0 = rows - chunk.len();
            for (r, ((t, vals), orow)) in chunk.iter().zip(&orows).enumerate() {
                compare_row(
                    row0 + r + 1,
                    t,
                    vals,
                    orow,
                    (rtol, atol),
                    &phi2_shift,
                    &mut stats,
                    &mut first,
                )?;
            }
            chunk.clear();
        }
        if done {
            break;
        }
    }
    if rows == 0 {
        return Err(Error::invalid("candidate", source, "has no data rows"));
    }
    Ok(CheckReport {
        case: case.name.clone(),
        rtol,
        atol,
        rows,
        columns: stats,
        first_failure: first,
        digits,
    })
}

/// One data row (1-based `row`) parsed against the header.
fn parse_row(
    line: &str,
    row: usize,
    cols: &[String],
    idx: &[usize],
    t_col: usize,
    source: &str,
) -> Result<(Exact, Vec<Cell>)> {
    let cells: Vec<&str> = line.split(',').map(|c| c.trim()).collect();
    if cells.len() != cols.len() {
        return Err(Error::invalid(
            "candidate",
            source,
            format!(
                "row {row} has {} fields, the header {}",
                cells.len(),
                cols.len()
            ),
        ));
    }
    let t = Exact::parse("t", cells[t_col], false).map_err(|_| {
        Error::invalid(
            "candidate",
            source,
            format!(
                "row {row}: t = {:?} is not a number",
                crate::error::shorten(cells[t_col])
            ),
        )
    })?;
    let mut vals = Vec::with_capacity(cells.len() - 1);
    for (k, cell) in cells.iter().enumerate() {
        if k == t_col {
            continue;
        }
        if idx[k] == MODE {
            vals.push((MODE, cell.to_string(), f64::NAN));
            continue;
        }
        let v: f64 = cell.parse().map_err(|_| {
            Error::invalid(
                "candidate",
                source,
                format!(
                    "row {row}, column {}: {:?} is not a number",
                    cols[k],
                    crate::error::shorten(cell)
                ),
            )
        })?;
        if !v.is_finite() {
            return Err(Error::invalid(
                "candidate",
                source,
                format!("row {row}, column {}: {cell} is not finite", cols[k]),
            ));
        }
        vals.push((idx[k], cell.to_string(), v));
    }
    Ok((t, vals))
}

/// Holds one row against the oracle's, updating the statistics.
#[allow(clippy::too_many_arguments)]
fn compare_row(
    row: usize,
    t: &Exact,
    vals: &[Cell],
    orow: &Row,
    (rtol, atol): (f64, f64),
    phi2_shift: &Float,
    stats: &mut [ColumnStats],
    first: &mut Option<FirstFailure>,
) -> Result<()> {
    let p = 128;
    for (j, (gi, text, _)) in vals.iter().enumerate() {
        if *gi == MODE {
            // the phase: the same mode, or flight
            let tag = orow.phase.tag();
            let st = &mut stats[j];
            let same = text.trim() == tag;
            if !same {
                st.failures += 1;
                st.worst_ratio = f64::INFINITY;
                st.worst_bound = "mode";
                if st.max_abs_t == "-" {
                    st.max_abs_t = t.to_string();
                }
                if first.is_none() {
                    *first = Some(FirstFailure {
                        row,
                        t: t.to_string(),
                        column: st.name.clone(),
                        candidate: text.clone(),
                        oracle: tag,
                        limit: 0.0,
                        bound: "mode",
                    });
                }
            } else if st.worst_bound == "-" {
                st.worst_bound = "mode";
            }
            continue;
        }
        let o = &orow.values[*gi];
        let mut cand = Exact::parse("value", text, false)?.to_float(p);
        if crate::motion::COLUMNS[*gi] == "phi2" {
            cand += phi2_shift;
        }
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
        let st = &mut stats[j];
        if abs > st.max_abs || st.max_abs_t == "-" {
            st.max_abs = abs;
            st.max_abs_t = t.to_string();
        }
        if !mag.is_zero() {
            let rel = Float::with_val(p, &err / &mag).to_f64();
            if st.max_rel.is_none_or(|m| rel > m) {
                st.max_rel = Some(rel);
                st.max_rel_t = t.to_string();
            }
        }
        let rel_term = Float::with_val(p, &mag * rtol);
        let bound = if rel_term > atol { "rtol" } else { "atol" };
        let limit = rel_term + atol;
        let ratio = if limit.is_zero() {
            if err.is_zero() {
                0.0
            } else {
                f64::INFINITY
            }
        } else {
            Float::with_val(p, &err / &limit).to_f64()
        };
        if ratio > st.worst_ratio || st.worst_bound == "-" {
            st.worst_ratio = ratio;
            st.worst_bound = bound;
        }
        if err > limit {
            st.failures += 1;
            if first.is_none() {
                *first = Some(FirstFailure {
                    row,
                    t: t.to_string(),
                    column: st.name.clone(),
                    candidate: text.clone(),
                    oracle: o.text.clone(),
                    limit: limit.to_f64(),
                    bound,
                });
            }
        }
    }
    Ok(())
}
