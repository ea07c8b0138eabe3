//! The audit of the paper's formulas against the first-principles mechanics
//! (issue 4). Not yet implemented.

use crate::error::{Error, Result};
use std::path::Path;

/// Runs the audit (all equations, or just `equation`), writes
/// `reports_dir/audit.md` when auditing everything, and returns the text to print.
pub fn run(equation: Option<&str>, reports_dir: &Path) -> Result<String> {
    let _ = (equation, reports_dir);
    Err(Error::not_physical("the audit is not implemented yet"))
}
