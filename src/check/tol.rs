//! Per-column tolerances: a value fails when |candidate − oracle| >
//! atol + rtol·|oracle|. By default every column has the same rtol and an
//! atol given in units of its natural scale
//! ([`crate::oracle::ladder::column_scales`]: time sqrt(r/g), angles 1,
//! lengths r, velocities sqrt(g r), rates sqrt(g/r), forces (m1 + m2) g,
//! work m2 g r); `--tol COLUMN=RTOL[,ATOL]` sets one column's rtol and,
//! when given, its atol in the column's own units.

use crate::error::{Error, Result};
use crate::model::Model;

/// The tolerance applied to one column.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tol {
    /// Relative tolerance.
    pub rtol: f64,
    /// Absolute tolerance, in the column's own units.
    pub atol: f64,
    /// The column's natural scale (atol of the defaults is in its units).
    pub scale: f64,
    /// Whether `--tol` set it.
    pub set: bool,
}

/// One `--tol` override: the column, its rtol, and its atol in the
/// column's own units (None: the default, `atol` × the column's scale).
#[derive(Debug, Clone, PartialEq)]
pub struct Override {
    /// Column name (any trajectory column but `t`).
    pub column: String,
    /// Relative tolerance.
    pub rtol: f64,
    /// Absolute tolerance in the column's units, if given.
    pub atol: Option<f64>,
}

/// A tolerance's text as a number: finite and >= 0, and either 0 or at
/// least 1e-300 (a positive number below binary64's range would be read as
/// 0, or as a subnormal of a few bits, and judged so); `None` otherwise.
pub fn tolerance_of(text: &str) -> Option<f64> {
    let v: f64 = text.trim().parse().ok()?;
    if !v.is_finite() || v < 0.0 || (v > 0.0 && v < 1e-300) {
        return None;
    }
    // zero only as a zero significand (`0`, `0.00`, `0e7`), not as `1e-400`
    let t = text.trim().trim_start_matches(['+', '-']);
    let sig = t.split(['e', 'E']).next().unwrap_or("");
    if v == 0.0 && !sig.bytes().all(|b| b == b'0' || b == b'.') {
        return None;
    }
    Some(v)
}

/// What a tolerance may be, for messages.
pub const TOLERANCE_ALLOWED: &str =
    "must be a finite number >= 0: 0, or from 1e-300 on (e.g. 1e-8)";

/// A tolerance named `name` ([`tolerance_of`]), or an error naming it.
pub fn tolerance(name: &str, text: &str) -> Result<f64> {
    tolerance_of(text).ok_or_else(|| Error::invalid(name, text, TOLERANCE_ALLOWED))
}

/// A tolerance value of `--tol` ([`tolerance_of`]).
fn tol_value(name: &str, spec: &str, text: &str) -> Result<f64> {
    match tolerance_of(text) {
        Some(v) => Ok(v),
        None => Err(Error::invalid(
            name,
            spec,
            format!("{text:?} is not a tolerance: expected COLUMN=RTOL[,ATOL] with numbers that are 0 or from 1e-300 to finite, e.g. theta=1e-3,1e-6"),
        )),
    }
}

/// The columns a tolerance may name.
pub fn tolerable_columns() -> Vec<&'static str> {
    crate::motion::COLUMNS[1..].to_vec()
}

/// Parses `COLUMN=RTOL[,ATOL]` (the value of `--tol`).
///
/// Errors: a missing `=`, an unknown column (or `t`, `mode`), a number that
/// is not finite and >= 0.
pub fn parse_override(spec: &str) -> Result<Override> {
    let (col, vals) = spec.split_once('=').ok_or_else(|| {
        Error::invalid(
            "tol",
            spec,
            "expected COLUMN=RTOL[,ATOL], e.g. theta=1e-3,1e-6",
        )
    })?;
    let col = col.trim();
    if !tolerable_columns().contains(&col) {
        return Err(Error::invalid(
            "tol",
            spec,
            format!(
                "unknown column {col:?}; allowed: {}",
                tolerable_columns().join(", ")
            ),
        ));
    }
    let mut parts = vals.split(',');
    let rtol = tol_value("tol", spec, parts.next().unwrap_or(""))?;
    let atol = parts
        .next()
        .map(|a| tol_value("tol", spec, a))
        .transpose()?;
    if parts.next().is_some() {
        return Err(Error::invalid(
            "tol",
            spec,
            "expected COLUMN=RTOL[,ATOL]: at most two numbers",
        ));
    }
    Ok(Override {
        column: col.to_string(),
        rtol,
        atol,
    })
}

/// The tolerance of every column of [`crate::motion::COLUMNS`] (`t`
/// included, unused): the defaults `rtol` and `atol` × scale, then the
/// overrides.
///
/// Errors: a global tolerance that is not finite and >= 0; an override
/// given twice.
pub fn tolerances(model: &Model, rtol: f64, atol: f64, over: &[Override]) -> Result<Vec<Tol>> {
    for (name, v) in [("rtol", rtol), ("atol", atol)] {
        if !v.is_finite() || v < 0.0 {
            return Err(Error::invalid(name, v, "must be a finite number >= 0"));
        }
    }
    let scales = crate::oracle::ladder::column_scales(model, 64);
    let mut out: Vec<Tol> = scales
        .iter()
        .map(|s| {
            let scale = s.to_f64();
            Tol {
                rtol,
                atol: atol * scale,
                scale,
                set: false,
            }
        })
        .collect();
    for (k, o) in over.iter().enumerate() {
        if over[..k].iter().any(|p| p.column == o.column) {
            return Err(Error::invalid(
                "tol",
                &o.column,
                "is given twice; give each column at most once",
            ));
        }
        let i = crate::motion::COLUMNS
            .iter()
            .position(|c| *c == o.column)
            .filter(|&i| i > 0)
            .ok_or_else(|| {
                Error::invalid(
                    "tol",
                    &o.column,
                    format!(
                        "is not a column; allowed: {}",
                        tolerable_columns().join(", ")
                    ),
                )
            })?;
        let t = &mut out[i];
        t.rtol = o.rtol;
        if let Some(a) = o.atol {
            t.atol = a;
        }
        t.set = true;
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn overrides_parse_and_refuse_what_they_cannot_read() {
        let o = parse_override("theta=1e-3,1e-6").unwrap();
        assert_eq!(
            (o.column.as_str(), o.rtol, o.atol),
            ("theta", 1e-3, Some(1e-6))
        );
        assert_eq!(parse_override(" N12 = 0 ").unwrap().atol, None);
        for bad in [
            "theta",
            "omega=1",
            "t=1",
            "mode=1",
            "theta=-1",
            "theta=1,x",
            "theta=1,2,3",
            "theta=inf",
        ] {
            let e = parse_override(bad).unwrap_err().to_string();
            assert!(e.contains("tol") && e.contains(bad.trim()), "{bad}: {e}");
        }
    }
}
