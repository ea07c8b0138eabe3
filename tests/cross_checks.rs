//! Independent routes must agree: forces and θ̈ from the reduced dynamics vs
//! the Lagrange-multiplier (KKT) system; Newton–Euler balance of each body;
//! conservation of energy and of the canonical momenta; the same digits at two
//! requested precisions. Tolerances scale with the working precision.

use cylroll::exact::Exact;
use cylroll::mechanics::dynamics::Dyn;
use cylroll::mechanics::kkt::{self, Bodies};
use cylroll::mechanics::Reduced;
use cylroll::model::{Contact, Floor, Ideal, Params, Start};
use cylroll::oracle::Oracle;
use rug::{Float, Rational};

fn q(s: &str) -> Rational {
    Exact::parse("q", s, false).unwrap().coef
}

const FLOORS: [Floor; 3] = [Floor::Roll, Floor::Slip, Floor::Fixed];
const CONTACTS: [Contact; 2] = [Contact::Roll, Contact::Slip];

/// Unequal everything, a bobbin (k2 > 1), and a start with θ̇0, ω0 ≠ 0.
fn cases() -> Vec<(Params, &'static str, &'static str, &'static str)> {
    let mut a = Params::identical_solid();
    a.m1 = q("3");
    a.m2 = q("1.25");
    a.r1 = q("0.7");
    a.r2 = q("1/3");
    a.k1 = q("0.4");
    a.k2 = q("0.9");
    a.g = q("9.81");
    let mut bobbin = Params::identical_solid();
    bobbin.k2 = q("3/2");
    bobbin.r1 = q("1/2");
    vec![
        (a.clone(), "0.05", "0", "0"),
        (bobbin, "1/10", "0", "0"),
        (a, "0.2", "0.3", "-0.7"),
    ]
}

fn close(a: &Float, b: &Float, scale: &Float, bits: i32, what: &str) {
    let d = Float::with_val(a.prec(), a - b).abs();
    let tol = Float::with_val(a.prec(), scale.clone().abs() + 1u32) >> bits;
    assert!(d <= tol, "{what}: {} vs {} (diff {:e})", a, b, d.to_f64());
}

#[test]
fn reduced_forces_match_lagrange_multipliers_and_newton_euler() {
    let prec = 400;
    let bits = prec as i32 - 24;
    for (params, th0, td0, w0) in cases() {
        for floor in FLOORS {
            for contact in CONTACTS {
                let w0 = if floor == Floor::Fixed { "0" } else { w0 };
                let start = Start {
                    theta0: Exact::parse("t", th0, false).unwrap(),
                    thetadot0: q(td0),
                    omega0: q(w0),
                };
                let m = Ideal::new(params.clone(), floor, contact, start).unwrap();
                let red = Reduced::new(&m).unwrap();
                let d = Dyn::new(&m, &red, prec).unwrap();
                let bodies = Bodies {
                    m1: d.m1.clone(),
                    m2: d.m2.clone(),
                    r1: d.r1.clone(),
                    r2: d.r2.clone(),
                    i1: d.i1.clone(),
                    i2: d.i2.clone(),
                    g: d.g.clone(),
                };
                let scale = Float::with_val(prec, &d.m1 + &d.m2) * &d.g;
                for delta in ["0.01", "0.3", "0.6"] {
                    let what =
                        format!("{floor:?}/{contact:?} th0={th0} td0={td0} w0={w0} delta={delta}");
                    let st = d.state(&Float::with_val(prec, &q(delta)));
                    let f = d.forces(&st);
                    let k = kkt::solve(&bodies, floor, contact, &st.theta, &st.thetadot).unwrap();
                    close(&f.f1, &k.f1, &scale, bits, &format!("F1 {what}"));
                    close(&f.n1, &k.n1, &scale, bits, &format!("N1 {what}"));
                    close(&f.f21, &k.f21, &scale, bits, &format!("F21 {what}"));
                    close(&f.n12, &k.n12, &scale, bits, &format!("N12 {what}"));
                    close(
                        &st.thetaddot,
                        &k.qdd[4],
                        &Float::with_val(prec, 1u32),
                        bits,
                        &format!("theta_ddot {what}"),
                    );
                    close(
                        &st.a[0],
                        &k.qdd[0],
                        &Float::with_val(prec, 1u32),
                        bits,
                        &format!("x1_ddot {what}"),
                    );
                    if floor != Floor::Slip || params.k1 != 0 {
                        close(
                            &st.a[1],
                            &k.qdd[2],
                            &Float::with_val(prec, 1u32),
                            bits,
                            &format!("phi1_ddot {what}"),
                        );
                    }
                    // Newton–Euler, body by body (n = (sinθ, cosθ), t = (cosθ, −sinθ))
                    let (s, c) = (&st.s, &st.c);
                    let td2 = Float::with_val(prec, st.thetadot.square_ref());
                    let (m1, m2, r, g) = (&d.m1, &d.m2, &d.r, &d.g);
                    let ax = &st.a[0];
                    // cylinder 2 centre acceleration
                    let a2x =
                        Float::with_val(prec, ax + Float::with_val(prec, r * &st.thetaddot) * c)
                            - Float::with_val(prec, r * &td2) * s;
                    let a2y = -(Float::with_val(prec, r * &st.thetaddot) * s)
                        - Float::with_val(prec, r * &td2) * c;
                    // force of 1 on 2: N12 n + F21 t
                    let fx = Float::with_val(prec, &f.n12 * s) + Float::with_val(prec, &f.f21 * c);
                    let fy = Float::with_val(prec, &f.n12 * c) - Float::with_val(prec, &f.f21 * s);
                    close(
                        &Float::with_val(prec, m2 * &a2x),
                        &fx,
                        &scale,
                        bits,
                        &format!("cyl2 x {what}"),
                    );
                    close(
                        &Float::with_val(prec, m2 * &a2y),
                        &Float::with_val(prec, &fy - Float::with_val(prec, m2 * g)),
                        &scale,
                        bits,
                        &format!("cyl2 y {what}"),
                    );
                    // cylinder 2 spin: I2 ψ̈2 = r2 F21
                    close(
                        &Float::with_val(prec, &d.i2 * &st.a[2]),
                        &Float::with_val(prec, &d.r2 * &f.f21),
                        &scale,
                        bits,
                        &format!("cyl2 spin {what}"),
                    );
                    // cylinder 1: floor force (F1, N1), minus the force on 2, gravity
                    if floor != Floor::Fixed {
                        close(
                            &Float::with_val(prec, m1 * ax),
                            &Float::with_val(prec, &f.f1 - &fx),
                            &scale,
                            bits,
                            &format!("cyl1 x {what}"),
                        );
                        // spin (clockwise φ1): −I1 φ̈1 = r1 (F1 + F21)
                        let lhs = -Float::with_val(prec, &d.i1 * &st.a[1]);
                        let rhs = Float::with_val(prec, &f.f1 + &f.f21) * &d.r1;
                        close(&lhs, &rhs, &scale, bits, &format!("cyl1 spin {what}"));
                    }
                    close(
                        &Float::with_val(prec, &f.n1 - &fy),
                        &Float::with_val(prec, m1 * g),
                        &scale,
                        bits,
                        &format!("cyl1 y {what}"),
                    );
                    if floor == Floor::Slip {
                        assert!(f.f1.is_zero() && k.f1.is_zero());
                    }
                }
            }
        }
    }
}

#[test]
fn energy_and_canonical_momenta_are_conserved_along_the_motion() {
    let prec = 300;
    let bits = prec as i32 - 20;
    for (params, th0, td0, w0) in cases() {
        for floor in FLOORS {
            for contact in CONTACTS {
                let w0 = if floor == Floor::Fixed { "0" } else { w0 };
                let start = Start {
                    theta0: Exact::parse("t", th0, false).unwrap(),
                    thetadot0: q(td0),
                    omega0: q(w0),
                };
                let m = Ideal::new(params.clone(), floor, contact, start).unwrap();
                let red = Reduced::new(&m).unwrap();
                let d = Dyn::new(&m, &red, prec).unwrap();
                let s0 = d.state(&Float::new(prec));
                let e0 = d.energy(&s0);
                let p0 = d.momenta(&s0);
                assert_eq!(p0.len(), red.cyclic.len());
                for delta in ["0.001", "0.25", "0.5", "0.8"] {
                    let st = d.state(&Float::with_val(prec, &q(delta)));
                    let what = format!("{floor:?}/{contact:?} th0={th0} delta={delta}");
                    close(&d.energy(&st), &e0, &e0, bits, &format!("energy {what}"));
                    for (a, b) in d.momenta(&st).iter().zip(&p0) {
                        close(a, b, b, bits, &format!("momentum {what}"));
                    }
                }
            }
        }
    }
}

#[test]
fn trajectory_is_consistent_with_its_own_time_integral_and_derivative() {
    // θ(t) from the trajectory, then t(θ) from the quadrature: round trip;
    // and a centred difference of θ(t) against θ̇ (error O(h²)).
    let m = Ideal::new(
        Params::identical_solid(),
        Floor::Roll,
        Contact::Roll,
        Start {
            theta0: Exact::parse("t", "0.2", false).unwrap(),
            thetadot0: q("0.1"),
            omega0: q("0.5"),
        },
    )
    .unwrap();
    let mut o = Oracle::new(&m, 30).unwrap();
    let h = "1e-6";
    let times: Vec<Exact> = ["2.999999", "3", "3.000001"]
        .iter()
        .map(|s| Exact::parse("t", s, false).unwrap())
        .collect();
    let rows = o.trajectory(&times).unwrap();
    let th: Vec<f64> = rows
        .iter()
        .map(|r| r[1].text.parse::<f64>().unwrap())
        .collect();
    let thd: f64 = rows[1][2].text.parse().unwrap();
    let fd = (th[2] - th[0]) / (2.0 * h.parse::<f64>().unwrap());
    assert!((fd - thd).abs() < 1e-9, "{fd} vs {thd}");
    let theta = Exact::parse("theta", &rows[1][1].text, false).unwrap();
    let t = o.time_at(&theta).unwrap();
    let tf: f64 = t.text.parse().unwrap();
    assert!((tf - 3.0).abs() < 1e-25);
    assert!(
        t.text.starts_with("3.0000000000000000000000000")
            || t.text.starts_with("2.9999999999999999999999999"),
        "{}",
        t.text
    );
}

#[test]
fn same_digits_at_two_requested_precisions() {
    for (floor, contact) in [
        (Floor::Roll, Contact::Roll),
        (Floor::Slip, Contact::Roll),
        (Floor::Roll, Contact::Slip),
    ] {
        let m = Ideal::new(
            Params::identical_solid(),
            floor,
            contact,
            Start::rest(Exact::parse("t", "1/20", false).unwrap()),
        )
        .unwrap();
        let a = Oracle::new(&m, 25).unwrap().separation().unwrap();
        let b = Oracle::new(&m, 120).unwrap().separation().unwrap();
        // the 120-digit answer rounded to 25 digits is the 25-digit answer
        let rb = cylroll::numeric::decimal::to_sig(&b.theta_s.value, 25);
        assert_eq!(a.theta_s.text, rb);
        let ta = a.t_s.unwrap();
        let tb = b.t_s.unwrap();
        assert_eq!(ta.text, cylroll::numeric::decimal::to_sig(&tb.value, 25));
    }
}

#[test]
fn mirror_image_motion() {
    let mk = |th0: &str, w0: &str| {
        Ideal::new(
            Params::identical_solid(),
            Floor::Roll,
            Contact::Roll,
            Start {
                theta0: Exact::parse("t", th0, false).unwrap(),
                thetadot0: q("0"),
                omega0: q(w0),
            },
        )
        .unwrap()
    };
    let mut right = Oracle::new(&mk("0.1", "0.3"), 25).unwrap();
    let mut left = Oracle::new(&mk("-0.1", "-0.3"), 25).unwrap();
    let a = right.separation().unwrap();
    let b = left.separation().unwrap();
    assert_eq!(format!("-{}", a.theta_s.text), b.theta_s.text);
    let fa = right
        .forces_at(&Exact::parse("t", "0.5", false).unwrap())
        .unwrap();
    let fb = left
        .forces_at(&Exact::parse("t", "-0.5", false).unwrap())
        .unwrap();
    for (x, y) in fa.iter().zip(&fb) {
        let odd = matches!(x.name.as_str(), "F1" | "F21" | "theta_dot" | "theta_ddot");
        if odd {
            let neg = match x.text.strip_prefix('-') {
                Some(r) => r.to_string(),
                None => format!("-{}", x.text),
            };
            assert_eq!(neg, y.text, "{}", x.name);
        } else {
            assert_eq!(x.text, y.text, "{}", x.name);
        }
    }
}
