//! The second route: time integration of the constrained equations (issue 3).
//! Not yet implemented.

use crate::error::{Error, Result};

/// Runs both routes on the built-in case set and returns the agreement table.
pub fn verify_report(digits: u32) -> Result<String> {
    let _ = digits;
    Err(Error::not_physical(
        "the second route is not implemented yet",
    ))
}

/// Solves a stack of cylinders described by `spec` and returns the report
/// (`json`: as a JSON object with decimal strings).
pub fn stack_report(spec: &str, digits: u32, json: bool) -> Result<String> {
    let _ = (spec, digits, json);
    Err(Error::not_physical("stacks are not implemented yet"))
}
