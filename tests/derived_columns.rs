//! The columns of a conservative phase's rows (θ̇ … s12 of the energy
//! route) are computed by the ladder's higher run alone, with the error
//! δ's verified bound and the formulas' roundings carry into them, instead
//! of against a lower run's values. Held here against the same tables at 45
//! digits, which verify the columns with a bound of their own a hundred
//! thousand million times smaller: every printed digit must be the 45-digit
//! value's, rounded, all the digits asked, and within the error bound
//! printed beside it — for every contact law of a conservative phase, from
//! rest and from a moving start, in SI units and in units beyond binary64's
//! range (g = 10^-330, where the error is measured instead), at the start,
//! at tiny times, and just before the separation, where N12 is a
//! cancellation of terms far larger than itself.

use cylroll::exact::Exact;
use cylroll::model::{Ideal, Law, Model, Params, Start, VARIANTS};
use cylroll::numeric::decimal::to_sig;
use cylroll::numeric::verify::Verified;
use cylroll::oracle::{self, Options};
use rug::{Float, Rational};

fn q(s: &str) -> Rational {
    Exact::parse("x", s, false).unwrap().coef
}

fn ex(s: &str) -> Exact {
    Exact::parse("t", s, true).unwrap()
}

fn model(floor: Law, contact: Law, params: Params, start: Start) -> Model {
    Model::new(params, floor, contact, start).unwrap()
}

fn rest() -> Start {
    Start::rest(Exact::parse("theta0", "1/10", false).unwrap())
}

/// The verified value `v` (at `v.digits` digits) is the reference's value
/// rounded to them.
fn agrees(v: &Verified, reference: &Verified, what: &str) {
    if v.text == "0" {
        // indistinguishable from zero at the digits asked: the reference's
        // value lies within the bound that said so
        let lim = Float::with_val(128, &v.err_bound + &reference.err_bound);
        assert!(
            Float::with_val(128, reference.value.abs_ref()) <= lim,
            "{what}: printed 0 (bound {}), the reference is {}",
            v.err_bound,
            reference.text
        );
        return;
    }
    assert!(v.digits > 0, "{what}: no digit");
    let want = to_sig(&reference.value, v.digits);
    assert_eq!(v.text, want, "{what}: {} digits", v.digits);
    // the error bound printed beside the value holds it: the reference
    // lies within the two bounds of the value computed
    let gap = Float::with_val(256, &v.value - &reference.value).abs();
    let lim = Float::with_val(256, &v.err_bound + &reference.err_bound);
    assert!(
        gap <= lim,
        "{what}: {} from the reference, beyond the bound {}",
        to_sig(&gap, 3),
        to_sig(&v.err_bound, 3)
    );
}

/// Every column of every row at 20 and 30 digits against 45.
fn check(m: &Model, times: &[Exact], label: &str) {
    let hi = oracle::trajectory(m, times, &Options::digits(45))
        .unwrap_or_else(|e| panic!("{label} at 45 digits: {e}"));
    for d in [20u32, 30] {
        let lo = oracle::trajectory(m, times, &Options::digits(d))
            .unwrap_or_else(|e| panic!("{label} at {d} digits: {e}"));
        assert_eq!(lo.columns, hi.columns);
        for (i, (a, b)) in lo.rows.iter().zip(&hi.rows).enumerate() {
            assert_eq!(a.phase, b.phase, "{label} row {i}");
            for ((v, r), name) in a.values.iter().zip(&b.values).zip(&lo.columns) {
                // t is the time asked, echoed exactly
                if name == "t" || (r.text == "0" && v.text == "0") {
                    continue;
                }
                agrees(
                    v,
                    r,
                    &format!("{label} at {d} digits, row {i} ({}), {name}", times[i]),
                );
                if v.text != "0" {
                    // the full digits asked, also where a value is far below
                    // its column's scale (N12 a hair from the separation)
                    assert!(
                        v.digits == d,
                        "{label} at {d} digits, row {i}, {name}: {} digits of {}",
                        v.digits,
                        v.text
                    );
                }
            }
        }
    }
}

/// The times of a table that stress the columns: the start, tiny times,
/// the middle, and — where the model separates — just before it.
fn times_for(m: &Model, t_unit: &str) -> Vec<Exact> {
    let sep = oracle::separation(m, &Options::digits(50)).unwrap();
    let mut t: Vec<Exact> = ["0", "1e-30", "1e-12", "1e-3", "1/3", "1"]
        .iter()
        .map(|s| Exact::rational(q(s) * q(t_unit)))
        .collect();
    if let Some(ts) = sep.value("t_s") {
        for back in ["1e-3", "1e-7", "1e-12", "1e-20", "1e-25"] {
            let x = q(&ts.text) - q(back) * q(t_unit);
            t.push(Exact::rational(x));
        }
    }
    // ascending, and before the model's end
    t.sort_by(|a, b| a.coef.cmp(&b.coef));
    t
}

#[test]
fn the_ideal_laws_columns_are_the_45_digit_ones_rounded() {
    for (floor, contact) in VARIANTS {
        let ideal = Ideal::new(Params::identical_solid(), floor, contact, rest()).unwrap();
        let m = Model::from_ideal(&ideal);
        let label = format!("{floor:?}/{contact:?}");
        check(&m, &times_for(&m, "1"), &label);
    }
}

#[test]
fn a_moving_start_and_coulomb_sticking_are_the_45_digit_ones_rounded() {
    let moving = Start {
        theta0: Exact::parse("theta0", "1/10", false).unwrap(),
        thetadot0: q("1/3"),
        omega0: q("2"),
    };
    let m = model(
        Law::Rolling,
        Law::Rolling,
        Params::identical_solid(),
        moving,
    );
    check(&m, &times_for(&m, "1"), "moving start");
    // Coulomb contacts sticking from rest: the energy route's phase up to the
    // slip onset, then the spectral route (rows there are compared as before)
    let mu = Law::parse_mu("mu", "0.3").unwrap();
    let m = model(mu.clone(), mu, Params::identical_solid(), rest());
    let times: Vec<Exact> = ["0", "1e-20", "0.5", "1", "2", "3", "3.5", "4"]
        .iter()
        .map(|s| ex(s))
        .collect();
    check(&m, &times, "mu = 0.3");
}

#[test]
fn si_units_and_units_beyond_binary64_are_the_45_digit_ones_rounded() {
    let mut si = Params::identical_solid();
    si.g = q("9.81");
    si.r1 = q("0.05");
    si.r2 = q("0.03");
    si.m1 = q("2");
    si.m2 = q("0.5");
    let m = model(Law::Rolling, Law::Rolling, si, rest());
    // the time unit sqrt(r/g) ≈ 0.09 s
    check(&m, &times_for(&m, "0.09"), "SI units");
    // g = 10^-330: the accelerations and forces below binary64's range; the
    // time unit 10^165
    let mut tiny = Params::identical_solid();
    tiny.g = q("1e-330");
    let m = model(Law::Rolling, Law::Rolling, tiny, rest());
    check(&m, &times_for(&m, "1e165"), "g = 1e-330");
}

/// Rows a hair from the end of the conservative phase (the slip onset of a
/// Coulomb contact, the separation of the ideal model), closer than the
/// lower precision tells apart: the side is decided at a higher precision,
/// and a run that places the row on the other side gives it the event's
/// state, which is compared with the other run's row — so both runs compute
/// such rows whole.
#[test]
fn rows_a_hair_from_the_end_of_the_phase_are_the_45_digit_ones_rounded() {
    let mu = Law::parse_mu("mu", "0.3").unwrap();
    let coulomb = model(mu.clone(), mu, Params::identical_solid(), rest());
    let ideal = model(
        Law::Rolling,
        Law::Rolling,
        Params::identical_solid(),
        rest(),
    );
    for (m, kind, label) in [
        (&coulomb, "slip_onset", "mu = 0.3"),
        (&ideal, "separation", "rolling"),
    ] {
        let sep = oracle::separation(m, &Options::digits(60)).unwrap();
        let ev = sep
            .events
            .iter()
            .find(|e| e.kind.name() == kind)
            .unwrap_or_else(|| panic!("{label}: no {kind}"));
        let te = q(&ev.t.text);
        let mut times: Vec<Exact> = ["-1e-20", "-1e-28", "-1e-31", "-1e-34"]
            .iter()
            .map(|d| Exact::rational(te.clone() + q(d)))
            .collect();
        // densely across the event (the two precisions' times of it differ
        // by some 10^-37: some of these lie between them)
        times.extend((-30..=30).map(|k| Exact::rational(te.clone() + q("3e-39") * k)));
        times.insert(0, ex("1"));
        check(m, &times, label);
    }
}
