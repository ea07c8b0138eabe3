//! Closed forms the oracle must reproduce to every requested digit. Each
//! expected value is computed here independently of the oracle (MPFR
//! elementary functions of an exact argument, or the Arb references of
//! `bench/anchors/ref/reference.json` copied below).

use cylroll::exact::Exact;
use cylroll::mechanics::Reduced;
use cylroll::model::{Contact, Floor, Ideal, Params, Start};
use cylroll::numeric::decimal::to_sig;
use cylroll::oracle::Oracle;
use rug::{Float, Rational};

fn q(s: &str) -> Rational {
    Exact::parse("q", s, false).unwrap().coef
}

fn model(floor: Floor, contact: Contact, k2: &str, m2: &str, theta0: &str) -> Ideal {
    let mut p = Params::identical_solid();
    p.k2 = q(k2);
    p.m2 = q(m2);
    Ideal::new(
        p,
        floor,
        contact,
        Start::rest(Exact::parse("theta0", theta0, true).unwrap()),
    )
    .unwrap()
}

/// acos(x) for an exact rational x, to `digits` significant digits.
fn acos_text(x: &Rational, digits: u32) -> String {
    let p = digits * 4 + 64;
    to_sig(&Float::with_val(p, x).acos(), digits)
}

#[test]
fn fixed_lower_cylinder_eq_36() {
    // footnote 8: cos θs = 2/(3 + k2): 2/3 (point / frictionless), 4/7 (solid), 10/17 (sphere-like k2 = 2/5)
    for (contact, k2, digits) in [
        (Contact::Slip, "1/2", 60),
        (Contact::Roll, "1/2", 60),
        (Contact::Roll, "2/5", 60),
        (Contact::Roll, "0", 40),
        (Contact::Roll, "1", 40),
        (Contact::Roll, "7/3", 200),
    ] {
        let m = model(Floor::Fixed, contact, k2, "1", "0");
        let mut o = Oracle::new(&m, digits).unwrap();
        let s = o.separation().unwrap();
        let k = if contact == Contact::Slip {
            Rational::new()
        } else {
            q(k2)
        };
        let c = Rational::from(2) / (Rational::from(3) + k);
        assert_eq!(s.theta_s.text, acos_text(&c, digits), "{contact:?} k2={k2}");
        assert!(s.t_s.is_none(), "rest at the top: infinite separation time");
    }
}

#[test]
fn identical_solid_cylinders_separate_at_pi_over_3() {
    // bench T2: for m1 = m2, k1 = k2 = 1/2 both rolling, θs = π/3 exactly
    for digits in [30, 300, 1000] {
        let m = Ideal::paper_default(Exact::zero());
        let mut o = Oracle::new(&m, digits).unwrap();
        let s = o.separation().unwrap();
        let pi3 = Float::with_val(digits * 4 + 64, rug::float::Constant::Pi) / 3u32;
        assert_eq!(s.theta_s.text, to_sig(&pi3, digits), "digits {digits}");
    }
}

#[test]
fn bench_t2b_non_degenerate_root() {
    // m2 = 2: θs = 1.094098559385214477287125461950827533993215543… (Arb, bench T2b)
    let m = model(Floor::Roll, Contact::Roll, "1/2", "2", "0");
    let mut o = Oracle::new(&m, 45).unwrap();
    let s = o.separation().unwrap();
    assert_eq!(
        s.theta_s.text,
        "1.09409855938521447728712546195082753399321554"
    );
}

#[test]
fn bench_t1_time_integral() {
    // T1 = 4.924315468243287509589438907674409756197297165837… (Arb, 1100 digits)
    let m = Ideal::paper_default(Exact::parse("theta0", "1/10", false).unwrap());
    let mut o = Oracle::new(&m, 48).unwrap();
    let t = o
        .time_at(&Exact::parse("to", "9/10", false).unwrap())
        .unwrap();
    assert_eq!(t.text, "4.92431546824328750958943890767440975619729716584");
}

#[test]
fn bench_t3_theta_at_t_end() {
    // θ(t_end) = 1.017720047898565541324320788879807079184492603… at
    // t_end = 5.146758983122540901696317082705216339477… (Arb reference)
    let m = Ideal::paper_default(Exact::parse("theta0", "1/10", false).unwrap());
    let mut o = Oracle::new(&m, 38).unwrap();
    let t_end = Exact::parse("t", "5.146758983122540901696317082705216339477", false).unwrap();
    let rows = o.trajectory(&[t_end]).unwrap();
    // t_end is given to 40 digits; θ̇ ≈ 0.56 so θ is determined to ~40 digits too
    assert_eq!(rows[0][1].text, "1.0177200478985655413243207888798070792");
}

#[test]
fn slip_slip_corrected_eq_43() {
    // Derived here: with P_x = 0 and (40), N12 = 0 gives
    //   m2 cos³θs = (m1 + m2)(3 cos θs − 2)
    // (the paper prints cos²). For m1 = m2 the root is cos θs = √3 − 1.
    let m = model(Floor::Slip, Contact::Slip, "1/2", "1", "0");
    let mut o = Oracle::new(&m, 50).unwrap();
    let s = o.separation().unwrap();
    let p = 300;
    let c = Float::with_val(p, 3u32).sqrt() - 1u32;
    assert_eq!(s.theta_s.text, to_sig(&c.acos(), 50));
    // and for m2 = 3 m1 (from the cubic 3c³ − 12c + 8 = 0, solved by bisection here)
    let m = model(Floor::Slip, Contact::Slip, "1/2", "3", "0");
    let mut o = Oracle::new(&m, 40).unwrap();
    let s = o.separation().unwrap();
    let (mut lo, mut hi) = (Float::with_val(p, 0.5), Float::with_val(p, 1u32));
    for _ in 0..p {
        let mid = Float::with_val(p, &lo + &hi) / 2u32;
        let cube = Float::with_val(p, mid.square_ref()) * &mid;
        let f = Float::with_val(p, cube * 3u32) - Float::with_val(p, &mid * 12u32) + 8u32;
        if f.is_sign_positive() {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    assert_eq!(s.theta_s.text, to_sig(&lo.acos(), 40));
}

#[test]
fn energy_forms_of_footnotes_6_and_11() {
    // footnote 6 (roll/roll, identical, k = 1/2): θ̇² = 12 g(1 − cos θ)/(a(17 + 4 cos θ − 4 cos²θ)), a = r/2
    //   ⇔ K(c) = (17 + 4c − 4c²)/12
    let red = Reduced::new(&Ideal::paper_default(Exact::zero())).unwrap();
    assert_eq!(red.q, [q("17/12"), q("1/3"), q("-1/3")]);
    // footnote 11 (slip/roll, k1 = k2 = 1/2): (3 m1 + 2 m2 sin²θ) θ̇² = 4 (m1+m2) g (1 − cos θ)/r
    //   ⇔ K(c) = (3 m1 + 2 m2 (1 − c²)) / (2 (m1 + m2)), for several mass ratios
    for (m1, m2) in [("1", "1"), ("2", "3"), ("7/10", "5")] {
        let mut p = Params::identical_solid();
        p.m1 = q(m1);
        p.m2 = q(m2);
        let m = Ideal::new(
            p.clone(),
            Floor::Slip,
            Contact::Roll,
            Start::rest(Exact::zero()),
        )
        .unwrap();
        let red = Reduced::new(&m).unwrap();
        let den = Rational::from(&p.m1 + &p.m2) * 2u32;
        let k0 = (Rational::from(&p.m1 * 3u32) + Rational::from(&p.m2 * 2u32)) / &den;
        let k2 = Rational::from(&p.m2 * -2i32) / &den;
        assert_eq!(red.q, [k0, Rational::new(), k2], "m1={m1} m2={m2}");
    }
}

#[test]
fn routh_roll_together_footnote_12() {
    // identical cylinders, frictionless floor, rolling contact: φ̇1 = θ̇ and φ2 = 0
    let mut p = Params::identical_solid();
    p.k1 = q("3/10");
    p.k2 = q("3/10");
    let m = Ideal::new(p, Floor::Slip, Contact::Roll, Start::rest(Exact::zero())).unwrap();
    let red = Reduced::new(&m).unwrap();
    // φ̇1 = (α + β c) θ̇ with α = 1, β = 0
    assert_eq!(red.alpha[1], Rational::from(1));
    assert_eq!(red.beta[1], Rational::new());
    // ψ̇2 = (r1 φ̇1 − r θ̇)/r2 = −θ̇ : φ2 = ψ2 + θ stays 0
    assert_eq!(red.alpha[2], Rational::from(-1));
    assert_eq!(red.beta[2], Rational::new());
}

/// cos θ* of identical solid cylinders rolling from rest at cos θ0 = `c0`:
/// the root of 2(c0 − c)/K(c) = c on (0, c0) by bisection (see below).
fn identical_solid_branch_point(c0: &Float, p: u32) -> Float {
    let k = Float::with_val(p, Rational::from((1, 2)));
    let h = |c: &Float| -> Float {
        let d = Float::with_val(p, c - &k);
        let kk = Float::with_val(p, &k + 1u32) - Float::with_val(p, d.square_ref()) / 3u32;
        Float::with_val(p, c0 - c) * 2u32 / kk - c
    };
    let (mut lo, mut hi) = (Float::new(p), c0.clone());
    for _ in 0..p {
        let mid = Float::with_val(p, &lo + &hi) / 2u32;
        if h(&mid).is_sign_positive() {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo
}

/// The branch point of a rolling pair: cylinder 1 alone on a rolling floor
/// (or held) has no horizontal acceleration, so once the cylinders may part
/// cylinder 2's free relative normal acceleration is r θ̇² − g cos θ. For
/// identical solid cylinders from rest at θ0, θ̇² = 2(g/r)(cos θ0 − c)/K(c)
/// with K = 1 + k2 − (c − k2)²/3 (eq. 23, confirmed by the audit), so it
/// turns positive where 2(cos θ0 − c)/K(c) = c (g/r = 1/2): bisection in c.
/// The answer on the default branch reports it and stays together to θs; on
/// the `part` branch the cylinders part there. For a held lower cylinder,
/// N12 = m2(g cos θ − r θ̇²): the two conditions coincide, no branch point.
#[test]
fn the_branch_point_of_the_rolling_main_case() {
    use cylroll::model::Model;
    use cylroll::motion::{Branch, Kind};
    use cylroll::oracle::{self, Options};
    let digits = 30;
    let p = 400;
    let c0 = Float::with_val(p, Rational::from((1, 10))).cos();
    let k = Float::with_val(p, Rational::from((1, 2)));
    let want = to_sig(&identical_solid_branch_point(&c0, p).acos(), digits);
    let m = Model::from_ideal(&model(Floor::Roll, Contact::Roll, "1/2", "1", "1/10"));
    let stay = oracle::separation(&m, &Options::digits(digits)).unwrap();
    assert_eq!(stay.value("theta_indeterminate").unwrap().text, want);
    let ev = stay.event(Kind::Indeterminate).unwrap();
    assert_eq!(ev.theta.text, want);
    // the closed branch goes on to N12 = 0
    let theta_s = stay.value("theta_s").unwrap().value.to_f64();
    assert!((theta_s - 1.050772062018511).abs() < 1e-14, "{theta_s}");
    let part = Options {
        branch: Branch::Part,
        ..Options::digits(digits)
    };
    let parted = oracle::separation(&m, &part).unwrap();
    assert_eq!(parted.value("theta_s").unwrap().text, want);
    // held lower cylinder: the branch point is the separation itself
    let held = Model::from_ideal(&model(Floor::Fixed, Contact::Roll, "1/2", "1", "1/10"));
    let a = oracle::separation(&held, &Options::digits(digits)).unwrap();
    assert!(a.event(Kind::Indeterminate).is_none(), "{:?}", a.notes);
    // cos θs = 2 cos θ0/(3 + k2)
    let c = Float::with_val(p, &c0 * 2u32) / Float::with_val(p, &k + 3u32);
    assert_eq!(a.value("theta_s").unwrap().text, to_sig(&c.acos(), digits));
}

/// From rest exactly at the top every time is infinite, but the closed
/// branch's angles are limits θ0 → 0+: the branch point too (c0 = 1 in the
/// closed form above; 0.96220953928886545929905906584675357888 by mpmath's
/// root of the cubic Π(c) of tests/fixtures/branch_derivation.md). On the
/// `part` branch θs is θ*; `--part-at` inside the window is where they part,
/// outside it is refused naming the window; a frictionless contact has no
/// branch point (its Π root is θs itself).
#[test]
fn the_branch_point_from_rest_at_the_top() {
    use cylroll::model::Model;
    use cylroll::motion::{Branch, Mode, State};
    use cylroll::oracle::{self, Options};
    let digits = 35;
    let p = 400;
    let want = to_sig(
        &identical_solid_branch_point(&Float::with_val(p, 1u32), p).acos(),
        digits,
    );
    assert_eq!(want, "0.96220953928886545929905906584675358");
    let m = Model::from_ideal(&model(Floor::Roll, Contact::Roll, "1/2", "1", "0"));
    let stay = oracle::separation(&m, &Options::digits(digits)).unwrap();
    assert_eq!(stay.value("theta_indeterminate").unwrap().text, want);
    assert_eq!(
        stay.start_mode,
        Some(Mode {
            floor: State::Stick,
            contact: State::Stick
        })
    );
    // θs = π/3 for identical solid cylinders from the top
    let pi3 = Float::with_val(p, rug::float::Constant::Pi) / 3u32;
    assert_eq!(stay.value("theta_s").unwrap().text, to_sig(&pi3, digits));
    let at = |branch: Branch| {
        oracle::separation(
            &m,
            &Options {
                branch,
                ..Options::digits(digits)
            },
        )
    };
    let parted = at(Branch::Part).unwrap();
    assert_eq!(parted.value("theta_s").unwrap().text, want);
    let one = at(Branch::PartAt(Exact::parse("part_at", "1", true).unwrap())).unwrap();
    assert!(one
        .value("theta_s")
        .unwrap()
        .text
        .starts_with("1.0000000000"));
    let err = at(Branch::PartAt(
        Exact::parse("part_at", "6/5", true).unwrap(),
    ))
    .unwrap_err()
    .to_string();
    assert!(
        err.contains("part-at") && err.contains("0.96220953"),
        "{err}"
    );
    let err = at(Branch::PartAt(
        Exact::parse("part_at", "0.9", true).unwrap(),
    ))
    .unwrap_err()
    .to_string();
    assert!(err.contains("part-at"), "{err}");
    // a frictionless contact: unique
    let slip = Model::from_ideal(&model(Floor::Roll, Contact::Slip, "1/2", "1", "0"));
    let a = oracle::separation(&slip, &Options::digits(digits)).unwrap();
    assert!(a.value("theta_indeterminate").is_none(), "{:?}", a.notes);
}

#[test]
fn a_light_upper_cylinder_separates_as_on_a_fixed_one() {
    // m2 = 10^-40 m1: the lower cylinder moves by O(m2/m1), far below the
    // 30 digits, so θs is the fixed cylinder's: cos θs = 2 cos θ0/(3 + k2)
    // (k2 = 0 on a frictionless contact), whatever the floor. The motion's
    // energy balance was measured with the potential's zero at the floor,
    // whose constant m1 g r1, rounded to 2^-p m1 g r, swamped the upper
    // cylinder's energy m2 g r: every law failed from m2 = 10^-6 m1 on
    use cylroll::model::{Law, Model};
    use cylroll::oracle::{self, Options};
    let theta0 = Rational::from((1, 10));
    let digits = 30;
    let p = digits * 4 + 64;
    let law = |s: &str| Law::parse_mu("mu", s).unwrap();
    for floor in ["inf", "0"] {
        for (contact, k) in [("inf", "1/2"), ("0", "0")] {
            let mut pr = Params::identical_solid();
            pr.m2 = q("1e-40");
            let start = Start::rest(Exact::parse("theta0", "1/10", true).unwrap());
            let m = Model::new(pr, law(floor), law(contact), start).unwrap();
            let s = oracle::separation(&m, &Options::digits(digits))
                .unwrap_or_else(|e| panic!("mu {floor}/{contact}: {e}"));
            let th = s.value("theta_s").expect("theta_s");
            let c = Float::with_val(p, &theta0).cos() * 2u32 / Float::with_val(p, q("3") + q(k));
            assert_eq!(th.text, to_sig(&c.acos(), digits), "mu {floor}/{contact}");
        }
    }
}

/// An upper cylinder 10^30 times the lower one, on a frictionless floor or
/// with a frictionless contact: θs by the polynomial route
/// (`separation_angle`: the polynomial in cos θ, isolated at 64 bits and
/// its coefficients' magnitude) against the energy route's θs (the root of
/// N12 along the quadrature's δ, which lost the lighter cylinder's terms at
/// most digits before it carried the bits of the mass ratio; at 30 digits:
/// `separation --m2 1e30 --floor slip`, `--contact slip`), at every digits.
#[test]
fn a_heavy_upper_cylinder_by_both_routes() {
    for (floor, contact, want) in [
        (
            Floor::Slip,
            Contact::Roll,
            "0.392634623838569937619437696974",
        ),
        (
            Floor::Roll,
            Contact::Slip,
            "0.343088606583533745971213131719",
        ),
    ] {
        let m = model(floor, contact, "1/2", "1e30", "1/10");
        let want = Float::with_val(256, Float::parse(want).unwrap());
        for digits in [3u32, 10, 15, 20] {
            let mut o = Oracle::new(&m, digits).unwrap();
            let v = o
                .separation_angle()
                .unwrap_or_else(|e| panic!("{floor:?}/{contact:?} {digits}: {e}"));
            assert_eq!(
                v.text,
                to_sig(&want, digits),
                "{floor:?}/{contact:?} {digits}"
            );
        }
    }
}
