//! Figures and tables (issue 6). Not yet implemented.

use crate::error::{Error, Result};
use std::path::Path;

/// Writes the report (figures, README.md, index.html) into `reports_dir` and
/// returns a summary to print. `progress` shows progress bars on stderr.
pub fn run(reports_dir: &Path, progress: bool) -> Result<String> {
    let _ = (reports_dir, progress);
    Err(Error::not_physical("the report is not implemented yet"))
}
