//! Reading models from key/value text: `--params` files, golden cases and flags
//! all go through here, so every input gets the same validation.

use crate::error::{Error, Result};
use crate::exact::Exact;
use crate::model::{Law, Model, Params, Start, Which};
use rug::Rational;
use std::collections::BTreeMap;

/// The keys a model accepts, in a stable order.
pub const MODEL_KEYS: [&str; 12] = [
    "floor",
    "contact",
    "m1",
    "m2",
    "r1",
    "r2",
    "k1",
    "k2",
    "g",
    "theta0",
    "thetadot0",
    "omega0",
];

/// The friction keys: `inf`, a number >= 0, or `S,K` (static, kinetic).
pub const FRICTION_KEYS: [&str; 2] = ["mu_floor", "mu_contact"];

/// The law of one contact from its keyword (`floor` / `contact`: roll,
/// slip, fixed, coulomb) and its coefficient (`mu_floor` / `mu_contact`),
/// either of which may be absent: a coefficient applies to a rolling (or
/// `coulomb`) contact; `0` agrees with `slip` (a rolling contact given μ = 0
/// is frictionless: the Python package always sends `roll` with its
/// coefficients), `inf` with `roll`; a held
/// cylinder has no floor coefficient (`none` is accepted, as echoed).
///
/// Errors: a keyword or coefficient that does not parse; a coefficient
/// that contradicts the keyword; `coulomb` without a coefficient.
pub fn law_of(vals: &Pairs, w: Which) -> Result<Law> {
    let kw_key = w.name();
    let mu_key = w.mu_key();
    let kw = vals.get(kw_key).map(|s| s.trim().to_ascii_lowercase());
    let mu = vals.get(mu_key);
    let coulomb_kw = kw.as_deref() == Some("coulomb");
    let base = match kw.as_deref() {
        None | Some("coulomb") => None,
        Some(_) => Some(Law::parse_keyword(w, &vals[kw_key])?),
    };
    let Some(mu_text) = mu else {
        if coulomb_kw {
            return Err(Error::invalid(
                kw_key,
                "coulomb",
                format!("needs its coefficient: give {mu_key} (a number >= 0 or S,K)"),
            ));
        }
        return Ok(base.unwrap_or(Law::Rolling));
    };
    if base == Some(Law::Held) {
        if mu_text.trim().eq_ignore_ascii_case("none") {
            return Ok(Law::Held);
        }
        return Err(Error::invalid(
            mu_key,
            mu_text,
            "a fixed floor (cylinder 1 held) has no floor contact: drop mu_floor",
        ));
    }
    let law = Law::parse_mu(mu_key, mu_text)?;
    match (&base, &law) {
        (Some(Law::Frictionless), Law::Frictionless) | (None | Some(Law::Rolling), _) => Ok(law),
        (Some(Law::Frictionless), _) => Err(Error::invalid(
            mu_key,
            mu_text,
            format!("contradicts {kw_key} = slip (frictionless, mu = 0): drop one of them"),
        )),
        _ => Ok(law),
    }
}

/// Keys of a golden case file besides the model's: `description` (one line
/// of prose) and `steps` (intervals of its time grid). A `--params` file may
/// carry them (so that every golden case is also a parameter file) and they
/// are ignored there.
pub const CASE_KEYS: [&str; 2] = ["description", "steps"];

/// Key → exact text.
pub type Pairs = BTreeMap<String, String>;

/// The model keys of a TOML table (other keys are an error unless listed in
/// `extra_keys`, which are skipped). Values must be strings or integers:
/// TOML floats are binary and would not be read exactly. The non-finite
/// TOML floats `inf`, `-inf` and `nan` are exact words, and are read as the
/// same text given to a flag (`mu_floor = inf` is rolling; `theta0 = inf`
/// is refused as `--theta0 inf` is).
pub fn pairs_from_toml(table: &toml::Table, source: &str, extra_keys: &[&str]) -> Result<Pairs> {
    let mut vals = Pairs::new();
    for (k, v) in table {
        if extra_keys.contains(&k.as_str()) {
            continue;
        }
        if !MODEL_KEYS.contains(&k.as_str()) && !FRICTION_KEYS.contains(&k.as_str()) {
            let mut allowed = format!("{}, {}", MODEL_KEYS.join(", "), FRICTION_KEYS.join(", "));
            if !extra_keys.is_empty() {
                allowed.push_str(&format!(" (and {}, ignored)", extra_keys.join(", ")));
            }
            return Err(Error::invalid(
                source,
                k,
                format!("unknown key; allowed keys: {allowed}"),
            ));
        }
        let s = match v {
            toml::Value::String(s) => s.clone(),
            toml::Value::Integer(i) => i.to_string(),
            toml::Value::Float(f) if f.is_nan() => "nan".into(),
            toml::Value::Float(f) if f.is_infinite() => {
                if *f > 0.0 { "inf" } else { "-inf" }.into()
            }
            toml::Value::Float(f) => {
                // `{:?}`: the shortest text that reads back as f (1e300, not 301 digits)
                return Err(Error::invalid(
                    k,
                    format!("{f:?}"),
                    format!(
                        "a TOML float is binary and would not be read exactly: \
                         write it as a string ({k} = \"{f:?}\") or an integer"
                    ),
                ));
            }
            other => {
                // a datetime as written (its Value's text is the TOML
                // library's private table)
                let written = match other {
                    toml::Value::Datetime(d) => d.to_string(),
                    _ => other.to_string(),
                };
                return Err(Error::invalid(
                    k,
                    written,
                    format!(
                        "expected an exact number as a string ({k} = \"0.3\") or an integer, \
                         not a TOML {}",
                        other.type_str()
                    ),
                ));
            }
        };
        vals.insert(k.clone(), s);
    }
    Ok(vals)
}

/// The model keys of a `--params` file (a golden case file is one: its
/// [`CASE_KEYS`] are accepted and ignored), as the command line and the
/// Python package read it.
///
/// Errors: those of [`read_toml`] and [`pairs_from_toml`], a key's error
/// naming the file.
pub fn read_params(path: &std::path::Path) -> Result<Pairs> {
    let table = read_toml(path, "params")?;
    pairs_from_toml(&table, "params", &CASE_KEYS).map_err(|e| in_file(e, path))
}

/// An error about a value read from the file `path`, naming the file:
/// `m1 (in p.toml)`.
pub fn in_file(e: Error, path: &std::path::Path) -> Error {
    e.map_invalid(|name, value| (format!("{name} (in {})", path.display()), value))
}

/// Largest parameter or case file read, in bytes.
pub const MAX_TOML_BYTES: u64 = 1 << 20;

/// The text of the input file `path`, given as parameter `what`: at most
/// `max_bytes` bytes (a larger file, or an endless one such as `/dev/zero`,
/// is refused without reading further), UTF-8, a leading byte-order mark
/// removed.
///
/// Errors: [`Error::Io`] naming `what` when the file cannot be opened or
/// read; [`Error::InvalidParameter`] naming `what` when it is too large or
/// not UTF-8.
pub fn read_input(path: &std::path::Path, what: &str, max_bytes: u64) -> Result<String> {
    use std::io::Read;
    let fail = |why: String| Error::invalid(what, path.display(), why);
    // a file that cannot be opened or read is an input-file error naming the parameter
    let io = |e: std::io::Error| Error::Io {
        path: path.display().to_string(),
        what: format!("{what} cannot be read: {e}"),
    };
    let file = std::fs::File::open(path).map_err(io)?;
    let mut bytes = Vec::new();
    file.take(max_bytes + 1)
        .read_to_end(&mut bytes)
        .map_err(io)?;
    if bytes.len() as u64 > max_bytes {
        return Err(fail(format!(
            "is larger than the {max_bytes} bytes allowed"
        )));
    }
    let text = String::from_utf8(bytes).map_err(|e| {
        fail(format!(
            "is not UTF-8 text (invalid byte at offset {})",
            e.utf8_error().valid_up_to()
        ))
    })?;
    Ok(strip_bom(&text).to_string())
}

/// `text` without a leading UTF-8 byte-order mark.
pub fn strip_bom(text: &str) -> &str {
    text.strip_prefix('\u{feff}').unwrap_or(text)
}

/// Parses TOML text read from `path` into a table.
pub fn read_toml(path: &std::path::Path, what: &str) -> Result<toml::Table> {
    let text = read_input(path, what, MAX_TOML_BYTES)?;
    text.parse()
        .map_err(|e: toml::de::Error| Error::invalid(what, path.display(), toml_refusal(&text, &e)))
}

/// A TOML parse error as a refusal: its message, and the line it is on
/// (its number and, shortened, its text) where the parser gives a place.
pub fn toml_refusal(text: &str, e: &toml::de::Error) -> String {
    let msg = e.message().trim();
    match e.span() {
        Some(span) if text.is_char_boundary(span.start) => {
            let start = text[..span.start].rfind('\n').map_or(0, |i| i + 1);
            let line = text[..span.start].matches('\n').count() + 1;
            let end = text[start..].find('\n').map_or(text.len(), |i| start + i);
            let shown = crate::error::shorten(text[start..end].trim());
            // TOML integers are 64-bit: a larger one is exact as text
            let hint = if msg.contains("too large") {
                "; give a number beyond 64-bit integers as text, key = \"…\""
            } else {
                ""
            };
            format!("not valid TOML at line {line} ({shown:?}): {msg}{hint}")
        }
        _ => format!("not valid TOML: {msg}"),
    }
}

/// Builds and validates a model from key/value pairs, as every entry point
/// builds it (flags, `--params`, golden cases, the Python package); missing
/// keys take the defaults (identical solid cylinders m = r = g = 1,
/// k = 1/2, both contacts rolling, from rest at θ0 = 0).
pub fn model_from_pairs(vals: &Pairs) -> Result<Model> {
    let get = |k: &str| vals.get(k).cloned();
    let num = |k: &str, default: Rational| -> Result<Rational> {
        match get(k) {
            None => Ok(default),
            Some(s) => Ok(Exact::parse(k, &s, false)?.coef),
        }
    };
    let d = Params::identical_solid();
    let params = Params {
        m1: num("m1", d.m1)?,
        m2: num("m2", d.m2)?,
        r1: num("r1", d.r1)?,
        r2: num("r2", d.r2)?,
        k1: num("k1", d.k1)?,
        k2: num("k2", d.k2)?,
        g: num("g", d.g)?,
    };
    let floor = law_of(vals, Which::Floor)?;
    let contact = law_of(vals, Which::Contact)?;
    let theta0 = match get("theta0") {
        None => Exact::zero(),
        Some(s) => Exact::parse("theta0", &s, true)?,
    };
    let start = Start {
        theta0,
        thetadot0: num("thetadot0", Rational::new())?,
        omega0: num("omega0", Rational::new())?,
    };
    Model::new(params, floor, contact, start).map_err(|e| as_given(e, vals))
}

/// An error about a key quoting the key's value as it was given (`-1e3`,
/// not the rational `-1000` the check saw).
fn as_given(e: Error, vals: &Pairs) -> Error {
    e.map_invalid(|name, value| {
        let value = match vals.get(&name) {
            Some(given) => crate::error::shorten(given.trim()),
            None => value,
        };
        (name, value)
    })
}
