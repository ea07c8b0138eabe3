//! The library's one error type.
//!
//! Every variant carries the numbers needed to understand it; the CLI maps
//! [`Error::exit_code`] to the process exit status.

use thiserror::Error;

/// Everything that can go wrong in cylroll.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum Error {
    /// A parameter or flag is outside its allowed range or cannot be parsed.
    #[error("invalid {name} = {value:?}: {allowed}")]
    InvalidParameter {
        name: String,
        value: String,
        allowed: String,
    },
    /// A request that has no finite or physical answer (e.g. a time from rest
    /// at the unstable equilibrium, a time after separation).
    #[error("{what}")]
    NotPhysical { what: String },
    /// A numerical method did not reach the requested accuracy, or (with
    /// `requested` 0) a decision the computation needs could not be made.
    #[error(
        "{quantity}: {} ({reached}); {detail}",
        if *requested == 0 { "not decided".to_string() } else { format!("could not verify {requested} digits") }
    )]
    NotConverged {
        quantity: String,
        requested: u32,
        reached: String,
        detail: String,
    },
    /// No sign change of the bracketing function on the interval searched.
    #[error("{quantity}: no sign change found on [{lo}, {hi}]")]
    NoSignChange {
        quantity: String,
        lo: String,
        hi: String,
    },
    /// An input file could not be read.
    #[error("{path}: {what}")]
    Io { path: String, what: String },
    /// An output file could not be written.
    #[error("cannot write {path}: {what}")]
    Write { path: String, what: String },
    /// The computation was stopped by its caller ([`crate::cancel`]).
    #[error("cancelled")]
    Cancelled,
}

impl Error {
    /// Process exit status for this error: 2 for bad input (including an
    /// unreadable input file) or a request with no physical answer, 3 for a
    /// numerical failure, 4 for an output file that cannot be written.
    pub fn exit_code(&self) -> i32 {
        match self {
            Error::InvalidParameter { .. } | Error::NotPhysical { .. } | Error::Io { .. } => 2,
            Error::NotConverged { .. } | Error::NoSignChange { .. } => 3,
            Error::Write { .. } => 4,
            Error::Cancelled => 130,
        }
    }

    /// Shorthand for [`Error::InvalidParameter`].
    ///
    /// A long value is shortened for the message (its start, its length).
    pub fn invalid(name: &str, value: impl ToString, allowed: impl ToString) -> Self {
        Error::InvalidParameter {
            name: name.to_string(),
            value: shorten(&value.to_string()),
            allowed: allowed.to_string(),
        }
    }

    /// An [`Error::InvalidParameter`] with its name and value given by `f`
    /// (from the old ones; e.g. the name with the file it was read from);
    /// any other error as it is.
    pub fn map_invalid(self, f: impl FnOnce(String, String) -> (String, String)) -> Self {
        match self {
            Error::InvalidParameter {
                name,
                value,
                allowed,
            } => {
                let (name, value) = f(name, value);
                Error::InvalidParameter {
                    name,
                    value,
                    allowed,
                }
            }
            other => other,
        }
    }

    /// An [`Error::NotConverged`] with its quantity and detail given by
    /// `f` (from the old ones; e.g. the file a quantity was read from, the
    /// unit the numbers are in); any other error as it is.
    pub fn map_not_converged(self, f: impl FnOnce(String, String) -> (String, String)) -> Self {
        match self {
            Error::NotConverged {
                quantity,
                requested,
                reached,
                detail,
            } => {
                let (quantity, detail) = f(quantity, detail);
                Error::NotConverged {
                    quantity,
                    requested,
                    reached,
                    detail,
                }
            }
            other => other,
        }
    }

    /// The error with `ctx` (e.g. the case or file a computation was
    /// asked by) before the text that leads its message; an input or
    /// output file's error (which names its path) and a cancellation as
    /// they are.
    pub fn context(self, ctx: &str) -> Self {
        match self {
            Error::InvalidParameter {
                name,
                value,
                allowed,
            } => Error::InvalidParameter {
                name: format!("{ctx}: {name}"),
                value,
                allowed,
            },
            Error::NotPhysical { what } => Error::NotPhysical {
                what: format!("{ctx}: {what}"),
            },
            Error::NotConverged { .. } => self.map_not_converged(|q, d| (format!("{ctx}: {q}"), d)),
            Error::NoSignChange { quantity, lo, hi } => Error::NoSignChange {
                quantity: format!("{ctx}: {quantity}"),
                lo,
                hi,
            },
            other => other,
        }
    }

    /// Shorthand for [`Error::NotPhysical`].
    pub fn not_physical(what: impl ToString) -> Self {
        Error::NotPhysical {
            what: what.to_string(),
        }
    }
}

/// Longest echo of a given value in a message, in characters.
pub const ECHO_MAX: usize = 60;

/// `text` cut to at most [`ECHO_MAX`] characters with its length noted, so
/// that a message stays one readable line whatever was given. Shortening a
/// shortened text changes nothing.
pub fn shorten(text: &str) -> String {
    let n = text.chars().count();
    if n <= ECHO_MAX {
        return text.to_string();
    }
    // the note "... (N characters)" is at most 27 characters for N < 10^10
    let head: String = text.chars().take(ECHO_MAX - 30).collect();
    format!("{head}... ({n} characters)")
}

/// Result alias used throughout the crate.
pub type Result<T> = std::result::Result<T, Error>;

#[cfg(test)]
mod tests {
    #[test]
    fn shorten_is_bounded_and_idempotent() {
        let long = "7".repeat(100_000);
        let s = super::shorten(&long);
        assert!(s.chars().count() <= super::ECHO_MAX, "{s}");
        assert!(s.ends_with("... (100000 characters)"), "{s}");
        assert_eq!(super::shorten(&s), s);
        assert_eq!(super::shorten("1e3"), "1e3");
    }

    /// A decision that could not be made says so; it never reads as a
    /// failure to verify "0 digits".
    #[test]
    fn an_undecided_decision_is_not_a_count_of_digits() {
        let e = |requested| super::Error::NotConverged {
            quantity: "mode".into(),
            requested,
            reached: "r".into(),
            detail: "d".into(),
        };
        assert_eq!(e(0).to_string(), "mode: not decided (r); d");
        assert_eq!(e(8).to_string(), "mode: could not verify 8 digits (r); d");
    }
}
