//! The fast routes against the references and against the routes they
//! replace: the Taylor integrator for θ(t) (bench T3 rows, the energy
//! quadrature, the trajectory's θ column), the polynomial separation root
//! (against `separation()`'s scan-and-refine), and the time integral by
//! tanh-sinh at p1 and Gauss–Legendre at p2 (against the Arb reference, and
//! the same digits before and after the rule is built); from 256 bits on the
//! Chebyshev time integral and from 600 bits on the Chebyshev inversion for
//! θ(t) (against Arb and against the Taylor route).
//!
//! Reference values are the Arb balls of `bench/anchors/ref` (made by `bench/anchors/reference.py` with Arb)
//! (reference.json, T3_reference.txt), copied here.

use cylroll::exact::Exact;
use cylroll::model::{Contact, Floor, Ideal, Params, Start};
use cylroll::numeric::decimal::to_sig;
use cylroll::oracle::Oracle;
use rug::{Float, Rational};

fn q(s: &str) -> Exact {
    Exact::parse("x", s, true).unwrap()
}

fn rounded(reference: &str, digits: u32) -> String {
    let f = Float::with_val(digits * 4 + 64, Float::parse(reference).unwrap());
    to_sig(&f, digits)
}

/// Bench T1 (Arb, first 320 digits).
const T1: &str = "4.924315468243287509589438907674409756197297165837008285148994610931355897460207772979764464245242302063771796498027081417317441550153566800001862957004773570231377933696009763174647401741774337995546002203979313279113924763814064325338007131039317339269455273019951136371986799037509921521052906924806835946999378806167";
/// Bench T2b (Arb).
const T2B: &str = "1.094098559385214477287125461950827533993215543405195872523622477219732370957697491796839431463256965543146819542899372330617615521827964581301720338922301005410997405000631008467107274165901370501744605709030775797536680507748972662782341968949002413765853255028543974828248486829262147974527326720959141300937027658265";
/// Bench T3: t_end and some rows i of θ(i·t_end/999) (Arb, 110 digits).
const T3_TEND: &str = "5.14675898312254090169631708270521633947776197330584879910456893909223260854511843882078068940435133427355809947833529851639293631353223";
const T3_ROWS: [(u32, &str); 7] = [
    (1, "0.10000046706532598866495584834317577640848124365603922659677337058159723240800433185166202940800184118817454772"),
    (37, "0.10064008817690437146995852485071630650893480953019178886175909438788129350118400466215553410699311018503591351"),
    (250, "0.13062575458410312366836286125117085142295512931984214897730893597905059116400854392642373901786408574337022055"),
    (500, "0.24092731838777861704829175024986325936386763363243209420399978664554533774453752456591155842429272411595820355"),
    (777, "0.53557496899447483109853834676981978845751738428798398124533374220447980142491457520829664755793429882154498862"),
    (998, "1.01484067186842801659760402774568257130022243752117589103855896513265561360916426760696077777773129050952107055"),
    (999, "1.01772004789856554132432078887980707918449260327807644975088123511602809941281270965137749309973304086448380853"),
];

fn t3_model() -> Ideal {
    Ideal::paper_default(q("1/10"))
}

fn t3_time(i: u32) -> Exact {
    Exact::rational(q(T3_TEND).coef * Rational::from((i, 999)))
}

#[test]
fn taylor_matches_the_bench_t3_rows_at_30_and_100_digits() {
    for digits in [30u32, 100] {
        let mut o = Oracle::new(&t3_model(), digits).unwrap();
        let times: Vec<Exact> = T3_ROWS.iter().map(|&(i, _)| t3_time(i)).collect();
        let th = o.theta_at_times(&times).unwrap();
        for ((i, want), v) in T3_ROWS.iter().zip(&th) {
            assert_eq!(v.digits, digits, "row {i}");
            assert_eq!(v.text, rounded(want, digits), "row {i} at {digits} digits");
        }
    }
}

/// What a user gets for T3 (the bench times it): θ from the answers every
/// law shares, on the `Model`, through the hybrid motion (past the branch
/// point at t = 5.05, on the default branch where the cylinders stay
/// together): the Arb rows, and the trajectory's θ column digit for digit.
#[test]
fn the_answers_on_the_model_match_the_bench_t3_rows() {
    use cylroll::model::Model;
    use cylroll::oracle::{self, Options};
    let m = Model::from_ideal(&t3_model());
    let times: Vec<Exact> = T3_ROWS.iter().map(|&(i, _)| t3_time(i)).collect();
    let rolling = cylroll::motion::Phase::parse("stick/stick").unwrap();
    for digits in [30u32, 100] {
        let opts = Options::digits(digits);
        let (th, phases) = oracle::theta_at_times(&m, &times, &opts).unwrap();
        for (((i, want), v), ph) in T3_ROWS.iter().zip(&th).zip(&phases) {
            assert_eq!(v.digits, digits, "row {i}");
            assert_eq!(v.text, rounded(want, digits), "row {i} at {digits} digits");
            assert_eq!(*ph, rolling, "row {i}");
        }
        let tr = oracle::trajectory(&m, &times, &opts).unwrap();
        for (row, v) in tr.rows.iter().zip(&th) {
            assert_eq!(row.values[1].text, v.text);
            assert_eq!(row.phase, rolling);
        }
    }
}

#[test]
fn theta_column_of_the_trajectory_is_theta_at_times() {
    let times: Vec<Exact> = [0u32, 3, 250, 999].iter().map(|&i| t3_time(i)).collect();
    let mut o = Oracle::new(&t3_model(), 40).unwrap();
    let rows = o.trajectory(&times).unwrap();
    let th = o.theta_at_times(&times).unwrap();
    for (r, t) in rows.iter().zip(&th) {
        assert_eq!(r[1].text, t.text);
    }
    assert_eq!(th[0].text, "0.1000000000000000000000000000000000000000");
}

#[test]
fn taylor_agrees_with_the_energy_quadrature() {
    // θ(t) by the Taylor route, then t(θ) by the quadrature: back to t. θ is
    // printed to 45 digits, so t comes back to about 45 digits (θ̇ ≈ 0.1–0.6).
    let digits = 45;
    let mut o = Oracle::new(&t3_model(), digits).unwrap();
    for t in ["1/3", "2", "4.5", "5.1"] {
        let th = o.theta_at_times(&[q(t)]).unwrap();
        let back = o.time_at(&q(&th[0].text)).unwrap();
        let p = 200;
        let diff = Float::with_val(p, Float::parse(&back.text).unwrap()) - q(t).to_float(p);
        assert!(
            diff.abs() < Float::with_val(p, 1e-40),
            "t = {t}: theta = {}, t(theta) = {}",
            th[0].text,
            back.text
        );
    }
}

#[test]
fn taylor_works_for_every_contact_model_and_a_moving_start() {
    // θ(t) against t(θ) for each contact model, a mirrored start and a start
    // with θ̇0 ≠ 0: the Taylor route and the quadrature route agree.
    let cases = [
        (Floor::Roll, Contact::Roll, "0.1", "0"),
        (Floor::Slip, Contact::Roll, "0.1", "0"),
        (Floor::Roll, Contact::Slip, "0.1", "0"),
        (Floor::Slip, Contact::Slip, "0.1", "0"),
        (Floor::Fixed, Contact::Roll, "0.1", "0"),
        (Floor::Roll, Contact::Roll, "-0.2", "-0.3"),
        (Floor::Roll, Contact::Roll, "0", "0.25"),
    ];
    for (floor, contact, th0, td0) in cases {
        let mut p = Params::identical_solid();
        p.k2 = Rational::from((2, 5));
        p.m2 = Rational::from(3);
        let start = Start {
            theta0: q(th0),
            thetadot0: q(td0).coef,
            omega0: Rational::new(),
        };
        let m = Ideal::new(p, floor, contact, start).unwrap();
        let mut o = Oracle::new(&m, 35).unwrap();
        let th = o.theta_at_times(&[q("1.5")]).unwrap();
        let back = o.time_at(&q(&th[0].text)).unwrap();
        let pr = 200;
        let diff = Float::with_val(pr, Float::parse(&back.text).unwrap()) - 1.5f64;
        assert!(
            diff.abs() < Float::with_val(pr, 1e-30),
            "{floor:?}/{contact:?} theta0 {th0} thetadot0 {td0}: theta = {}, t = {}",
            th[0].text,
            back.text
        );
    }
}

#[test]
fn separation_angle_is_separation_theta_s() {
    let mut cases = vec![];
    for (floor, contact) in cylroll::model::VARIANTS {
        for (m2, k2, th0, td0) in [
            ("1", "1/2", "0", "0"),
            ("2", "1/2", "1/10", "0"),
            ("1/3", "3/2", "-1/5", "-1/4"),
        ] {
            cases.push((floor, contact, m2, k2, th0, td0));
        }
    }
    for (floor, contact, m2, k2, th0, td0) in cases {
        let mut p = Params::identical_solid();
        p.m2 = q(m2).coef;
        p.k2 = q(k2).coef;
        let start = Start {
            theta0: q(th0),
            thetadot0: q(td0).coef,
            omega0: Rational::new(),
        };
        let m = Ideal::new(p, floor, contact, start).unwrap();
        for digits in [20u32, 60] {
            let mut o = Oracle::new(&m, digits).unwrap();
            let fast = o.separation_angle().unwrap();
            let full = o.separation().unwrap().theta_s;
            assert_eq!(
                fast.text, full.text,
                "{floor:?}/{contact:?} m2 {m2} k2 {k2} theta0 {th0} thetadot0 {td0} at {digits}"
            );
        }
    }
}

#[test]
fn time_integral_matches_the_bench_t1_value_to_300_digits() {
    let mut o = Oracle::new(&t3_model(), 300).unwrap();
    assert_eq!(o.time_at(&q("9/10")).unwrap().text, rounded(T1, 300));
}

#[test]
fn separation_angle_matches_the_bench_t2b_root_to_300_digits() {
    let mut p = Params::identical_solid();
    p.m2 = Rational::from(2);
    let m = Ideal::new(p, Floor::Roll, Contact::Roll, Start::rest(Exact::zero())).unwrap();
    let mut o = Oracle::new(&m, 300).unwrap();
    assert_eq!(o.separation_angle().unwrap().text, rounded(T2B, 300));
    // T2: exactly π/3
    let mut o = Oracle::new(&Ideal::paper_default(Exact::zero()), 300).unwrap();
    let pi3 = Float::with_val(1300, rug::float::Constant::Pi) / 3u32;
    assert_eq!(o.separation_angle().unwrap().text, to_sig(&pi3, 300));
}

#[test]
fn time_integral_by_both_second_runs() {
    // the first calls run tanh-sinh at both precisions; once a Gauss–Legendre
    // rule pays for itself (here by the third call), it takes the second run:
    // the digits must not move (the routes themselves are compared in the
    // oracle's unit tests)
    let mut o = Oracle::new(&t3_model(), 120).unwrap();
    let want = rounded(T1, 120);
    for _ in 0..6 {
        let t = o.time_at(&q("9/10")).unwrap();
        assert_eq!(t.text, want);
    }
}

#[test]
fn taylor_is_independent_of_the_time_unit() {
    // g = 1000 and g = 1/1000 are the same motion with time scaled by
    // 1/√1000 and √1000: θ at the scaled time must agree, and come back
    // through the quadrature
    let digits = 32;
    let mut thetas = vec![];
    for (g, t) in [
        ("1", "3.6"),
        ("1000", "0.113841995766062"),
        ("1/1000", "113.841995766062"),
    ] {
        let mut p = Params::identical_solid();
        p.g = q(g).coef;
        let m = Ideal::new(p, Floor::Roll, Contact::Roll, Start::rest(q("1/10"))).unwrap();
        let mut o = Oracle::new(&m, digits).unwrap();
        let th = o.theta_at_times(&[q(t)]).unwrap();
        let back = o.time_at(&q(&th[0].text)).unwrap();
        let pr = 200;
        let rel = (Float::with_val(pr, Float::parse(&back.text).unwrap()) - q(t).to_float(pr))
            / q(t).to_float(pr);
        assert!(
            rel.abs() < 1e-28,
            "g = {g}: theta {} t {}",
            th[0].text,
            back.text
        );
        thetas.push(th[0].text.clone());
    }
    // the scaled times are rounded to 15 digits: θ agrees to about that
    for t in &thetas[1..] {
        assert_eq!(t[..14], thetas[0][..14], "{thetas:?}");
    }
}

/// From 256 bits on (here 300 digits) t(θ) is integrated by Chebyshev
/// interpolation: every digit of Arb's T1.
#[test]
fn chebyshev_time_matches_arb_t1_at_300_digits() {
    let mut o = Oracle::new(&t3_model(), 300).unwrap();
    let v = o.time_at(&q("9/10")).unwrap();
    assert_eq!(v.digits, 300);
    assert_eq!(v.text, rounded(T1, 300));
}

/// From 600 bits on (here 200 digits) θ(t) comes from Newton's method on
/// the Chebyshev antiderivative: the bench T3 rows (110 digits of Arb).
#[test]
fn chebyshev_inversion_matches_the_bench_t3_rows() {
    let mut o = Oracle::new(&t3_model(), 200).unwrap();
    let times: Vec<Exact> = T3_ROWS.iter().map(|&(i, _)| t3_time(i)).collect();
    let th = o.theta_at_times(&times).unwrap();
    for ((i, want), v) in T3_ROWS.iter().zip(&th) {
        assert_eq!(v.digits, 200, "row {i}");
        let got = to_sig(&Float::with_val(900, Float::parse(&v.text).unwrap()), 105);
        assert_eq!(got, rounded(want, 105), "row {i}");
    }
}

/// The trajectory by the Taylor route (130 digits: both working precisions
/// below 600 bits) and by the Chebyshev route (200 digits: both above)
/// agree in every column to 130 digits, on models whose integrands differ:
/// a moving start (the integrand in v carries a factor v), a slipping
/// floor, a slipping contact, a held lower cylinder, a hollow upper one.
#[test]
fn chebyshev_and_taylor_trajectories_agree() {
    let moving = Start {
        theta0: q("1/5"),
        thetadot0: Rational::from((1, 4)),
        omega0: Rational::new(),
    };
    let mut hollow = Params::identical_solid();
    hollow.k2 = Rational::from(1);
    let models = [
        Ideal::new(
            Params::identical_solid(),
            Floor::Roll,
            Contact::Roll,
            moving,
        )
        .unwrap(),
        Ideal::new(
            Params::identical_solid(),
            Floor::Slip,
            Contact::Roll,
            Start::rest(q("3/10")),
        )
        .unwrap(),
        Ideal::new(
            Params::identical_solid(),
            Floor::Roll,
            Contact::Slip,
            Start::rest(q("1/4")),
        )
        .unwrap(),
        Ideal::new(
            Params::identical_solid(),
            Floor::Fixed,
            Contact::Roll,
            Start::rest(q("1/5")),
        )
        .unwrap(),
        Ideal::new(hollow, Floor::Roll, Contact::Roll, Start::rest(q("1/10"))).unwrap(),
    ];
    let mut compared = 0;
    for (mi, m) in models.iter().enumerate() {
        let ts = {
            let mut o = Oracle::new(m, 20).unwrap();
            o.separation().unwrap().t_s.expect("finite").value.to_f64()
        };
        // three times inside the motion, the last close to separation
        let times: Vec<Exact> = [0.01, 0.5, 0.97]
            .iter()
            .map(|f| Exact::rational(Rational::from_f64(ts * f).unwrap()))
            .collect();
        let mut lo = Oracle::new(m, 130).unwrap();
        let a = lo.trajectory(&times).unwrap();
        let mut hi = Oracle::new(m, 200).unwrap();
        let b = hi.trajectory(&times).unwrap();
        for (ra, rb) in a.iter().zip(&b) {
            for (va, vb) in ra.iter().zip(rb).skip(1) {
                if va.digits < 130 || vb.digits < 200 || va.text.starts_with(">=") {
                    continue;
                }
                let got = to_sig(&Float::with_val(900, Float::parse(&vb.text).unwrap()), 130);
                assert_eq!(got, va.text, "model {mi}, column {}", va.name);
                compared += 1;
            }
        }
    }
    // 5 models × 3 times × 12 columns, less the exact zeros of frictionless
    // contacts and held cylinders
    assert!(compared >= 120, "compared {compared}");
}

/// A long table at 200 digits finds its rows by the Taylor run (both
/// working precisions below 800 bits, more than 250 rows: the run's fixed
/// part is cheaper than an inversion per row there), a few of its times
/// alone by the Chebyshev inversion: every value the same text, on the main
/// case from rest and on a slipping floor from a moving start.
#[test]
fn a_long_table_by_the_taylor_run_is_the_few_times_by_inversion() {
    use cylroll::integrate::energy::inversion_pays;
    use cylroll::numeric::verify::precisions;
    let (p1, p2) = precisions(200, 0);
    assert!(!inversion_pays(p1, 300) && !inversion_pays(p2, 300));
    assert!(inversion_pays(p1, 4) && inversion_pays(p2, 4));
    let moving = Start {
        theta0: q("1/5"),
        thetadot0: Rational::from((1, 4)),
        omega0: Rational::new(),
    };
    let models = [
        Ideal::paper_default(q("1/10")),
        Ideal::new(
            Params::identical_solid(),
            Floor::Slip,
            Contact::Roll,
            moving,
        )
        .unwrap(),
    ];
    for (mi, m) in models.iter().enumerate() {
        let ts = {
            let mut o = Oracle::new(m, 20).unwrap();
            o.separation().unwrap().t_s.expect("finite").value.to_f64()
        };
        // 300 times on [0, 0.95 t_s], each a multiple of 1/1000
        let step = (ts * 0.95 / 300.0 * 1000.0).floor() as i64;
        let times: Vec<Exact> = (0..300)
            .map(|i| Exact::rational(Rational::from((i * step, 1000))))
            .collect();
        let long = Oracle::new(m, 200).unwrap().trajectory(&times).unwrap();
        let few_at = [1usize, 77, 150, 299];
        let few_times: Vec<Exact> = few_at.iter().map(|&i| times[i].clone()).collect();
        let few = Oracle::new(m, 200).unwrap().trajectory(&few_times).unwrap();
        let mut compared = 0;
        for (&i, row) in few_at.iter().zip(&few) {
            for (a, b) in long[i].iter().zip(row) {
                assert_eq!(a.text, b.text, "model {mi}, row {i}, {}", a.name);
                if a.digits == 200 {
                    compared += 1;
                }
            }
        }
        assert!(
            compared >= 4 * 10,
            "model {mi}: {compared} values of 200 digits"
        );
    }
}

/// From rest at θ0 = 1e-100 the motion stays linear for a long time:
/// θ(t) = θ0 cosh(λt), λ² = θ̈/θ at the top = 6/17 for identical solid
/// cylinders, with a relative correction O(θ²) far below the digits asked.
/// The trajectory takes the graded Chebyshev route there at every precision
/// (the Taylor run could not follow: exit 3 after 26 s).
#[test]
fn trajectory_from_very_near_the_top_is_the_linear_motion() {
    let m = Ideal::paper_default(q("1e-100"));
    for (digits, times) in [(30u32, vec!["97", "194"]), (100, vec!["97"])] {
        let mut o = Oracle::new(&m, digits).unwrap();
        let ts: Vec<Exact> = times.iter().map(|t| q(t)).collect();
        let rows = o.trajectory(&ts).unwrap();
        for (t, row) in times.iter().zip(&rows) {
            let p = 800;
            let lambda = Float::with_val(p, Rational::from((6, 17))).sqrt();
            let arg = lambda * Float::with_val(p, Float::parse(t).unwrap());
            let want = Float::with_val(p, Float::parse("1e-100").unwrap()) * arg.cosh();
            assert_eq!(row[1].digits, digits, "t = {t}");
            assert_eq!(
                row[1].text,
                to_sig(&want, digits),
                "t = {t} at {digits} digits"
            );
        }
    }
}

/// Found by the property test: with θ̇0 ≠ 0 the integrand in v vanishes at
/// v = 0, and a Newton error constant taken over the whole first piece was
/// infinite, so θ(t) by the Chebyshev inversion had an infinite error bound
/// (exit 3 at every precision from 600 bits on). The constant is now taken
/// at the root.
#[test]
fn chebyshev_inversion_from_a_moving_start_on_a_held_cylinder() {
    let params = Params {
        m1: Rational::from((1, 10)),
        m2: Rational::from((1, 10)),
        r1: Rational::from((3, 5)),
        r2: Rational::from((14, 5)),
        k1: Rational::new(),
        k2: Rational::new(),
        g: Rational::from(1),
    };
    let start = Start {
        theta0: q("3/20"),
        thetadot0: Rational::from((1, 10)),
        omega0: Rational::new(),
    };
    let m = Ideal::new(params, Floor::Fixed, Contact::Roll, start).unwrap();
    let t = [q("1.997953303458")];
    let a = Oracle::new(&m, 40).unwrap().theta_at_times(&t).unwrap();
    let b = Oracle::new(&m, 190).unwrap().theta_at_times(&t).unwrap();
    assert_eq!(b[0].digits, 190);
    let got = to_sig(&Float::with_val(900, Float::parse(&b[0].text).unwrap()), 40);
    assert_eq!(got, a[0].text);
}

/// At a tiny time the motion from rest is θ0 + θ̈0 t²/2 (the next term is
/// t² smaller), and the last-time certificate compares t(θ ∓ ε) with room
/// ε·dt/dθ = ε/θ̇: it was ε·θ̇, too strict where θ̇ < 1 (here 1e-51: exit 3
/// at every precision of the Chebyshev route) and too lenient where θ̇ > 1.
#[test]
fn a_tiny_time_from_rest_is_the_parabola() {
    let m = t3_model();
    let t = Exact::parse("t", "1e-50", false).unwrap();
    for digits in [100u32, 200] {
        let rows = Oracle::new(&m, digits)
            .unwrap()
            .trajectory(std::slice::from_ref(&t))
            .unwrap();
        let acc = Oracle::new(&m, digits + 20)
            .unwrap()
            .forces_at(&q("1/10"))
            .unwrap();
        let thdd = &acc.iter().find(|v| v.name == "theta_ddot").unwrap().value;
        let p = 4 * digits + 200;
        let tt = Float::with_val(p, Float::parse("1e-50").unwrap());
        let want =
            Float::with_val(p, tt.square_ref()) * thdd / 2u32 + Float::with_val(p, 1u32) / 10u32;
        assert_eq!(rows[0][1].digits, digits);
        assert_eq!(rows[0][1].text, to_sig(&want, digits), "{digits}");
    }
}

/// A tiny time from a moving start: θ = θ0 + θ̇0 t + θ̈0 t²/2 + O(t³). The
/// integrand in v vanishes at v = 0 there and T(v) ≈ f'(0) v²/2, so a tiny
/// τ cancelled in the inversion's low-precision steps (21 of 200 digits,
/// exit 3); the seed now comes from that leading term and the steps work
/// as many bits higher as τ lies below T's span.
#[test]
fn a_tiny_time_from_a_moving_start_is_the_taylor_polynomial() {
    let start = Start {
        theta0: q("1/5"),
        thetadot0: Rational::from((1, 4)),
        omega0: Rational::new(),
    };
    let m = Ideal::new(Params::identical_solid(), Floor::Roll, Contact::Roll, start).unwrap();
    for (digits, t) in [(100u32, "1e-40"), (200, "1e-80"), (200, "1e-400")] {
        let te = Exact::parse("t", t, false).unwrap();
        let rows = Oracle::new(&m, digits)
            .unwrap()
            .trajectory(std::slice::from_ref(&te))
            .unwrap();
        let acc = Oracle::new(&m, digits + 20)
            .unwrap()
            .forces_at(&q("1/5"))
            .unwrap();
        let thdd = &acc.iter().find(|v| v.name == "theta_ddot").unwrap().value;
        let p = 4 * digits + 400;
        let tt = Float::with_val(p, Float::parse(t).unwrap());
        let want = Float::with_val(p, tt.square_ref()) * thdd / 2u32
            + Float::with_val(p, &tt / 4u32)
            + Float::with_val(p, 1u32) / 5u32;
        assert_eq!(rows[0][1].digits, digits, "{t}");
        assert_eq!(
            rows[0][1].text,
            to_sig(&want, digits),
            "{digits} digits at t = {t}"
        );
    }
}

/// A table whose early rows need δ to full relative accuracy (x1, φ1, φ2 are
/// of order δ ≈ θ̈0 t²/2, 2e-12 at t = 1e-5) and whose later rows do not: the
/// Taylor route (below 600 bits) takes the early ones from a short run with
/// the extra fixed-point bits and the rest from a run without them. Every
/// column of every row matches the same table at 200 digits (the Chebyshev
/// route) rounded to 30, and the small columns carry all 30 digits.
#[test]
fn early_rows_keep_their_relative_digits_beside_late_ones() {
    let m = t3_model();
    let times: Vec<Exact> = ["0.00001", "0.001", "0.05", "0.7", "2", "4.5"]
        .iter()
        .map(|t| q(t))
        .collect();
    let lo = Oracle::new(&m, 30).unwrap().trajectory(&times).unwrap();
    let first = cylroll::numeric::verify::precisions(30, 0);
    let hi = Oracle::new(&m, 200).unwrap().trajectory(&times).unwrap();
    for (r, (a, b)) in lo.iter().zip(&hi).enumerate() {
        assert_eq!(a[0].text, b[0].text, "t is printed as given");
        for (va, vb) in a.iter().zip(b).skip(1) {
            if vb.text == "0" {
                assert_eq!(va.text, "0", "{} row {r}", va.name);
                continue;
            }
            assert_eq!(va.digits, 30, "{} row {r}", va.name);
            assert_eq!(va.text, rounded(&vb.text, 30), "{} row {r}", va.name);
            // verified at the ladder's first rung: the early rows' δ had
            // its relative digits without climbing
            assert_eq!(va.precs, first, "{} row {r}", va.name);
        }
    }
    // the small columns really are small at the first row
    let x1 = Float::parse(&lo[0][6].text).map(|f| Float::with_val(64, f));
    assert_eq!(lo[0][6].name, "x1");
    assert!(x1.unwrap().abs() < 1e-10);
}
