//! The `--stack SPEC` syntax: a stack of n ≥ 2 cylinders (paper footnote 3).
//!
//! A SPEC is a list of `key=value` items separated by `;`. Lists are
//! comma-separated, bottom up; a list with one value applies it to every
//! cylinder (or line of centres). Numbers are exact (`0.3` is 3/10, `1/3`,
//! `1e-3`; angles may be written `pi/6`). Keys:
//!
//! | key | meaning | default |
//! |---|---|---|
//! | `n` | number of cylinders, 2 ≤ n ≤ 12 | required |
//! | `floor` | `roll`, `slip` or `fixed` (cylinder 1 on the floor) | `roll` |
//! | `contacts` | n−1 of `roll` / `slip`, cylinder j+1 on cylinder j | `roll` |
//! | `m` | n masses | `1` |
//! | `r` | n radii | `1` |
//! | `k` | n inertia factors, I = k m r² | `1/2` |
//! | `g` | gravity | `1` |
//! | `theta0` | n−1 initial angles of the lines of centres, clockwise from vertical (absolute, radians) | required |
//! | `thetadot0` | n−1 initial angular velocities of the lines of centres | `0` |
//! | `omega0` | rate of common rolling fixing the conserved momenta | `0` |
//! | `tmax` | stop here if no contact has opened (units of time) | `200·sqrt((r1+r2)/g)` |
//!
//! Example: `n=3;floor=roll;m=1,1,1;r=1,1,1;k=1/2,1/2,1/2;theta0=0.1,0.05;contacts=roll,roll`.

use crate::error::{Error, Result};
use crate::exact::Exact;
use crate::mechanics::system::StackModel;
use crate::model::{Contact, Floor};
use rug::Rational;

/// The text returned by `stack_report("help", ..)`.
pub const HELP: &str = "\
cylroll verify --stack SPEC: a stack of n cylinders (paper footnote 3), each rolling or slipping
on the one below, the lowest on the floor. Solved by the second route only (time integration of
the Lagrange-multiplier equations); every value is verified at two working precisions.

SPEC: key=value items separated by ';'. Lists are comma-separated, bottom up; one value applies
to all. Numbers are exact (0.3 = 3/10, 1/3, 1e-3; angles may be pi/6).

  n          number of cylinders, 2 <= n <= 12                         (required)
  floor      roll | slip | fixed: how cylinder 1 meets the floor        (default roll)
  contacts   n-1 of roll | slip: cylinder j+1 on cylinder j             (default roll)
  m          n masses                                                   (default 1)
  r          n radii                                                    (default 1)
  k          n inertia factors, I = k m r^2                             (default 1/2)
  g          gravity                                                    (default 1)
  theta0     n-1 angles of the lines of centres, clockwise from the
             vertical, absolute (not relative to the line below)        (required)
  thetadot0  n-1 initial angular velocities of the lines of centres     (default 0)
  omega0     common rolling rate fixing the conserved momenta: the
             state with every thetadot = 0 and the same momenta has
             phi1_dot = omega0, x1_dot = r1 omega0, each spin rolling
             on the one below                                           (default 0)
  tmax       give up if no contact opens before this time               (default 200 sqrt((r1+r2)/g))

Coordinates: x1, y1, phi1 (cylinder 1, clockwise), then per line of centres j = 1..n-1:
psi_{j+1} (cylinder j+1, counter-clockwise), theta_j, r_j. Forces: N1, F1 from the floor on
cylinder 1; N_{j,j+1} normal force between cylinders j and j+1 (positive while pressing);
F_{j+1,j} tangential force of cylinder j on cylinder j+1 along (cos theta_j, -sin theta_j).

The report names the contact that opens first (the first normal force to vanish: N1 of the
floor or N_{j,j+1}), its time and the angles there, the turning points (theta_j_dot = 0)
passed on the way, and the conservation of energy and of the canonical momenta (one for a
rolling floor and rolling contacts: the momentum conjugate to phi1).

Example:
  cylroll verify --stack 'n=3;floor=roll;m=1,1,1;r=1,1,1;k=1/2,1/2,1/2;theta0=0.1,0.05;contacts=roll,roll'
";

/// Largest n accepted.
pub const MAX_N: usize = 12;

fn list(key: &str, v: &str, allow_pi: bool) -> Result<Vec<Exact>> {
    v.split(',')
        .map(|t| Exact::parse(key, t, allow_pi))
        .collect()
}

fn rational(key: &str, e: Exact) -> Result<Rational> {
    e.as_rational()
        .cloned()
        .ok_or_else(|| Error::invalid(key, &e, "must be a rational number (no pi)"))
}

fn expand<T: Clone>(key: &str, v: Vec<T>, len: usize) -> Result<Vec<T>> {
    if v.len() == len {
        Ok(v)
    } else if v.len() == 1 {
        Ok(vec![v[0].clone(); len])
    } else {
        Err(Error::invalid(
            key,
            format!("{} values", v.len()),
            format!("give {len} values (or one for all)"),
        ))
    }
}

/// A parsed SPEC: the model and the time limit (None: the default).
#[derive(Debug, Clone, PartialEq)]
pub struct Spec {
    /// The stack.
    pub model: StackModel,
    /// `tmax`, if given.
    pub tmax: Option<Rational>,
}

/// Parses a SPEC (see the module documentation).
///
/// Errors: [`Error::InvalidParameter`] naming the key.
pub fn parse(spec: &str) -> Result<Spec> {
    let mut n: Option<usize> = None;
    let mut items: Vec<(String, String)> = Vec::new();
    for item in spec.split(';') {
        let item = item.trim();
        if item.is_empty() {
            continue;
        }
        let (k, v) = item.split_once('=').ok_or_else(|| {
            Error::invalid(
                "stack",
                item,
                "expected key=value items separated by ';' (see --stack help)",
            )
        })?;
        let k = k.trim().to_ascii_lowercase();
        let v = v.trim().to_string();
        if items.iter().any(|(a, _)| *a == k) {
            return Err(Error::invalid(&k, &v, "given twice"));
        }
        if k == "n" {
            let x: usize = v
                .parse()
                .map_err(|_| Error::invalid("n", &v, format!("an integer 2..={MAX_N}")))?;
            if !(2..=MAX_N).contains(&x) {
                return Err(Error::invalid(
                    "n",
                    &v,
                    format!("must be between 2 and {MAX_N}"),
                ));
            }
            n = Some(x);
        }
        items.push((k, v));
    }
    let n = n.ok_or_else(|| Error::invalid("n", "", "missing: give n=<number of cylinders>"))?;
    let one = Rational::from(1);
    let mut model = StackModel {
        floor: Floor::Roll,
        contacts: vec![Contact::Roll; n - 1],
        m: vec![one.clone(); n],
        r: vec![one.clone(); n],
        k: vec![Rational::from((1, 2)); n],
        g: one,
        theta0: Vec::new(),
        thetadot0: vec![Rational::new(); n - 1],
        omega0: Rational::new(),
    };
    let mut tmax = None;
    let mut have_theta = false;
    for (k, v) in items {
        match k.as_str() {
            "n" => {}
            "floor" => model.floor = v.parse()?,
            "contacts" => {
                let c: Vec<Contact> = v
                    .split(',')
                    .map(|s| s.trim().parse::<Contact>())
                    .collect::<Result<_>>()?;
                model.contacts = expand("contacts", c, n - 1)?;
            }
            "m" | "r" | "k" => {
                let vals: Vec<Rational> = list(&k, &v, false)?
                    .into_iter()
                    .map(|e| rational(&k, e))
                    .collect::<Result<_>>()?;
                let vals = expand(&k, vals, n)?;
                match k.as_str() {
                    "m" => model.m = vals,
                    "r" => model.r = vals,
                    _ => model.k = vals,
                }
            }
            "g" => model.g = rational("g", Exact::parse("g", &v, false)?)?,
            "theta0" => {
                model.theta0 = expand("theta0", list("theta0", &v, true)?, n - 1)?;
                have_theta = true;
            }
            "thetadot0" => {
                let vals: Vec<Rational> = list("thetadot0", &v, false)?
                    .into_iter()
                    .map(|e| rational("thetadot0", e))
                    .collect::<Result<_>>()?;
                model.thetadot0 = expand("thetadot0", vals, n - 1)?;
            }
            "omega0" => model.omega0 = rational("omega0", Exact::parse("omega0", &v, false)?)?,
            "tmax" => {
                let t = rational("tmax", Exact::parse("tmax", &v, false)?)?;
                if t <= 0 {
                    return Err(Error::invalid("tmax", &v, "must be > 0"));
                }
                tmax = Some(t);
            }
            other => {
                return Err(Error::invalid(
                    other,
                    &v,
                    "unknown key; expected n, floor, contacts, m, r, k, g, theta0, thetadot0, omega0, tmax",
                ))
            }
        }
    }
    if !have_theta {
        return Err(Error::invalid(
            "theta0",
            "",
            "missing: give the n-1 initial angles of the lines of centres",
        ));
    }
    model.validate()?;
    if model.starts_at_equilibrium() {
        return Err(Error::not_physical(
            "the stack starts at rest exactly on the vertical: it never moves (every time is infinite)",
        ));
    }
    Ok(Spec { model, tmax })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_the_documented_example() {
        let s = parse(
            "n=3;floor=roll;m=1,1,1;r=1,1,1;k=1/2,1/2,1/2;theta0=0.1,0.05;contacts=roll,roll",
        )
        .unwrap();
        assert_eq!(s.model.n(), 3);
        assert_eq!(s.model.theta0[1].coef, Rational::from((1, 20)));
        assert!(s.tmax.is_none());
    }

    #[test]
    fn defaults_and_broadcast() {
        let s = parse("n=4; theta0=pi/40; contacts=slip; floor=slip").unwrap();
        assert_eq!(s.model.contacts, vec![Contact::Slip; 3]);
        assert_eq!(s.model.k, vec![Rational::from((1, 2)); 4]);
        assert!(s.model.theta0[2].times_pi);
    }

    #[test]
    fn errors_name_the_key() {
        for (spec, key) in [
            ("theta0=0.1", "n"),
            ("n=3;theta0=0.1,0.2;m=1,2", "m"),
            ("n=3;theta0=0.1,0.2;floor=ice", "floor"),
            ("n=3;theta0=0.1,0.2;colour=red", "colour"),
            ("n=1;theta0=0.1", "n"),
            ("n=2", "theta0"),
            ("n=2;theta0=2", "theta0"),
            ("n=2;theta0=0.1;r=0", "r"),
        ] {
            match parse(spec) {
                Err(Error::InvalidParameter { name, .. }) => assert_eq!(name, key, "{spec}"),
                other => panic!("{spec}: {other:?}"),
            }
        }
    }
}
