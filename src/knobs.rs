//! Environment knobs: whole numbers a user may set by environment variable
//! (how many blocks of a long table run at once, how many rows a block
//! holds). A knob set to a value it cannot take is refused by name, with
//! what was given and what is allowed, never ignored.

use crate::error::{Error, Result};

/// The whole number in `1..=max` that the environment variable `name` is set
/// to, `None` when it is not set. `what`: what the number counts, for the
/// message.
///
/// Errors: `name` set to anything else (not a whole number, 0, above `max`,
/// not valid Unicode).
pub fn count(name: &str, max: usize, what: &str) -> Result<Option<usize>> {
    let Some(raw) = std::env::var_os(name) else {
        return Ok(None);
    };
    let given = raw.to_string_lossy();
    given
        .trim()
        .parse::<usize>()
        .ok()
        .filter(|n| (1..=max).contains(n))
        .map(Some)
        .ok_or_else(|| {
            Error::invalid(
                name,
                &given,
                format!("a whole number from 1 to {max} ({what})"),
            )
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Unset: none; set: the number, or a refusal naming the variable, the
    /// value and the range (each case on a variable of its own: the tests
    /// run in parallel).
    #[test]
    fn a_knob_is_its_number_or_refused_by_name() {
        assert_eq!(count("CYLROLL_KNOB_TEST_UNSET", 9, "x").unwrap(), None);
        std::env::set_var("CYLROLL_KNOB_TEST_SET", " 7 ");
        assert_eq!(count("CYLROLL_KNOB_TEST_SET", 9, "x").unwrap(), Some(7));
        for (i, bad) in ["0", "10", "-1", "two", "", "1.5"].iter().enumerate() {
            let name = format!("CYLROLL_KNOB_TEST_BAD{i}");
            std::env::set_var(&name, bad);
            let msg = count(&name, 9, "things counted").unwrap_err().to_string();
            assert!(
                msg.contains(&name) && msg.contains("from 1 to 9 (things counted)"),
                "{bad:?}: {msg}"
            );
        }
    }
}
