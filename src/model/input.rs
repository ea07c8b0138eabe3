//! Reading models from key/value text: `--params` files, golden cases and flags
//! all go through here, so every input gets the same validation.

use crate::error::{Error, Result};
use crate::exact::Exact;
use crate::model::{Contact, Floor, Model, Params, Start};
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

/// The friction keys (`inf`, a number >= 0, or `S,K`), read by
/// [`friction_from_pairs`].
pub const FRICTION_KEYS: [&str; 2] = ["mu_floor", "mu_contact"];

/// The friction laws of key/value pairs (`roll` limits where absent).
///
/// Errors: a coefficient that does not parse or is out of range.
pub fn friction_from_pairs(vals: &Pairs) -> Result<crate::motion::Friction> {
    use crate::motion::Law;
    let law = |k: &str| -> Result<Law> {
        match vals.get(k) {
            None => Ok(Law::Roll),
            Some(s) => Law::parse(k, s),
        }
    };
    Ok(crate::motion::Friction {
        floor: law("mu_floor")?,
        contact: law("mu_contact")?,
    })
}

/// [`friction_from_pairs`] checked against the model's contacts: a
/// coefficient given for a fixed floor, or `inf` (rolling) given for a
/// contact the model declares frictionless, contradicts the model.
///
/// Errors: as [`friction_from_pairs`], and those contradictions.
pub fn friction_for(vals: &Pairs, model: &Model) -> Result<crate::motion::Friction> {
    use crate::motion::Law;
    let fr = friction_from_pairs(vals)?;
    if let Some(v) = vals.get("mu_floor") {
        if model.floor() == Floor::Fixed {
            return Err(Error::invalid(
                "mu_floor",
                v,
                "a fixed floor (cylinder 1 held) has no floor contact: drop mu_floor",
            ));
        }
        if model.floor() == Floor::Slip && fr.floor == Law::Roll {
            return Err(Error::invalid(
                "mu_floor",
                v,
                "inf is a rolling floor, which contradicts floor = slip",
            ));
        }
    }
    if let Some(v) = vals.get("mu_contact") {
        if model.contact() == Contact::Slip && fr.contact == Law::Roll {
            return Err(Error::invalid(
                "mu_contact",
                v,
                "inf is a rolling contact, which contradicts contact = slip",
            ));
        }
    }
    Ok(fr)
}

/// Keys of a golden case file besides the model's; a `--params` file may
/// carry them (so that every golden case is also a parameter file) and they
/// are ignored there.
pub const CASE_KEYS: [&str; 2] = ["description", "steps"];

/// The model and its friction laws from key/value pairs, as every entry
/// point builds them (flags, `--params`, golden cases, the Python package):
/// the laws checked against the model, the model made the equal ideal one
/// where a law is an ideal limit, and the friction `None` when no contact has
/// a finite coefficient.
///
/// Errors: as [`model_from_pairs`], [`friction_for`] and
/// [`crate::motion::check_laws`].
pub fn model_and_friction(vals: &Pairs) -> Result<(Model, Option<crate::motion::Friction>)> {
    let model = model_from_pairs(vals)?;
    let fr = friction_for(vals, &model)?;
    crate::motion::check_laws(&model, &fr)?;
    let eff = crate::motion::effective_model(&model, &fr)?;
    let coulomb = fr.floor.is_coulomb() || fr.contact.is_coulomb();
    Ok((eff, coulomb.then_some(fr)))
}

/// Key → exact text.
pub type Pairs = BTreeMap<String, String>;

/// The model keys of a TOML table (other keys are an error unless listed in
/// `extra_keys`, which are skipped). Values must be strings or integers:
/// TOML floats are binary and would not be read exactly.
pub fn pairs_from_toml(table: &toml::Table, source: &str, extra_keys: &[&str]) -> Result<Pairs> {
    let mut vals = Pairs::new();
    for (k, v) in table {
        if extra_keys.contains(&k.as_str()) {
            continue;
        }
        if !MODEL_KEYS.contains(&k.as_str()) && !FRICTION_KEYS.contains(&k.as_str()) {
            return Err(Error::invalid(
                source,
                k,
                format!(
                    "unknown key; allowed keys: {}, {}",
                    MODEL_KEYS.join(", "),
                    FRICTION_KEYS.join(", ")
                ),
            ));
        }
        let s = match v {
            toml::Value::String(s) => s.clone(),
            toml::Value::Integer(i) => i.to_string(),
            toml::Value::Float(f) => {
                return Err(Error::invalid(
                    k,
                    f,
                    format!(
                        "a TOML float is binary and would not be read exactly: \
                         write it as a string ({k} = \"{f}\") or an integer"
                    ),
                ))
            }
            other => {
                return Err(Error::invalid(
                    k,
                    other,
                    format!(
                        "expected an exact number as a string ({k} = \"0.3\") or an integer, \
                         not a TOML {}",
                        other.type_str()
                    ),
                ))
            }
        };
        vals.insert(k.clone(), s);
    }
    Ok(vals)
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
    text.parse().map_err(|e: toml::de::Error| {
        Error::invalid(
            what,
            path.display(),
            format!("not valid TOML: {}", e.message().trim()),
        )
    })
}

/// Builds and validates a model from key/value pairs; missing keys take the
/// defaults (identical solid cylinders m = r = g = 1, k = 1/2, both contacts
/// rolling, from rest at θ0 = 0).
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
    let floor: Floor = get("floor").as_deref().unwrap_or("roll").parse()?;
    let contact: Contact = get("contact").as_deref().unwrap_or("roll").parse()?;
    let theta0 = match get("theta0") {
        None => Exact::zero(),
        Some(s) => Exact::parse("theta0", &s, true)?,
    };
    let start = Start {
        theta0,
        thetadot0: num("thetadot0", Rational::new())?,
        omega0: num("omega0", Rational::new())?,
    };
    Model::new(params, floor, contact, start)
}
