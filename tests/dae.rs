//! The second route (time integration of the Lagrange-multiplier equations)
//! against the first (energy quadrature), and the stacks of footnote 3.
//!
//! Tolerances scale with the requested digits. Every check names the case,
//! the quantity and both values when it fails.

use cylroll::crosscheck::*;
use cylroll::exact::Exact;
use cylroll::integrate::solve::Sample;
use cylroll::mechanics::kkt::{self, Bodies};
use cylroll::mechanics::system::{self, Row, StackModel, System};
use cylroll::model::{Contact, Floor, Ideal, Params, Start};
use cylroll::numeric::bits_for_digits;
use cylroll::oracle::Oracle;
use cylroll::stack::{solve_stack, spec, stack_report};
use rug::ops::Pow;
use rug::{Float, Rational};

fn q(s: &str) -> Rational {
    Exact::parse("q", s, false).unwrap().coef
}

/// Every row of a two-route comparison agrees to at least `digits` digits;
/// a row without an agreement count is a value both routes print as 0.
fn assert_routes_agree(case: &str, rep: &CaseReport, digits: u32) {
    for r in &rep.rows {
        if let Some(a) = r.agree {
            assert!(
                a >= digits,
                "{case} {}: routes agree to {a} digits only: route 1 {} vs route 2 {}",
                r.quantity,
                r.route1.text,
                r.route2.text
            );
        } else {
            assert_eq!(r.route1.text, "0", "{case} {}", r.quantity);
        }
    }
}

fn ten_pow(prec: u32, e: i32) -> Float {
    Float::with_val(prec, 10u32).pow(e)
}

/// Every case of `cargo run -- verify`: each contact model, the bobbin, the
/// starts with θ̇0, ω0 ≠ 0, a start to the left: every quantity (θs, ts, the
/// sign-change angles, F21 at separation, and θ, θ̇, θ̈, φ1, φ2, x1, x2, y2,
/// F1, N1, F21, N12 at three times) agrees to the requested digits, and the
/// second route's constraint drift, energy and momentum changes stay below
/// the requested precision.
#[test]
fn routes_agree_for_every_case_at_30_digits() {
    let digits = 30;
    let small = ten_pow(64, -(digits as i32) - 2);
    let all = cases();
    assert!(all.len() >= 10);
    let names: Vec<&str> = all.iter().map(|c| c.name.as_str()).collect();
    for want in [
        "roll-roll",
        "roll-slip",
        "slip-roll",
        "slip-slip",
        "fixed-roll",
        "fixed-slip",
        "bobbin",
        "moving-roll",
        "moving-slip",
    ] {
        assert!(names.contains(&want), "case {want} missing");
    }
    for case in &all {
        let rep = compare_case(case, digits).unwrap_or_else(|e| panic!("{}: {e}", case.name));
        assert!(
            rep.rows.len() >= 38,
            "{}: {} rows",
            case.name,
            rep.rows.len()
        );
        assert_routes_agree(&case.name, &rep, digits);
        let run = &rep.run;
        for (what, v) in [
            ("constraint drift", &run.run.max_drift),
            ("energy change", &run.energy_drift),
            ("momentum change", &run.momentum_drift),
        ] {
            assert!(
                *v < small,
                "{}: {what} {:e} not below 1e-{}",
                case.name,
                v.to_f64(),
                digits + 2
            );
        }
    }
}

/// The table of `cylroll verify`: one section per case, a summary line.
#[test]
fn verify_report_table() {
    let rep = verify_report(12).unwrap();
    let text = rep.text();
    // deterministic: no wall-clock time in the report (only in timings())
    assert!(!text.contains(" s (route 1"), "{text}");
    assert!(rep.timings().contains("route 2"));
    // every format it accepts: JSON parses, CSV has one row per quantity
    let v: serde_json::Value = serde_json::from_str(&rep.json()).unwrap();
    assert_eq!(v["command"], "verify");
    let n_rows: usize = v["sections"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["rows"].as_array().unwrap().len())
        .sum();
    assert_eq!(rep.csv().lines().count(), n_rows + 1);
    assert!(rep.csv().starts_with("kind,case,quantity,agree,value\n"));
    assert!(text.contains("## roll-roll:"), "{text}");
    assert!(text.contains("## bobbin:"), "{text}");
    assert!(text.contains("theta_s"), "{text}");
    let summary = text
        .lines()
        .find(|l| l.starts_with("# summary"))
        .expect("summary");
    let least: u32 = summary
        .split("at least ")
        .nth(1)
        .and_then(|s| s.split(' ').next())
        .and_then(|s| s.parse().ok())
        .expect("digits in summary");
    assert!(least >= 12, "{summary}");
}

fn bodies(sys: &System) -> Bodies {
    Bodies {
        m1: sys.m[0].clone(),
        m2: sys.m[1].clone(),
        r1: sys.rho[0].clone(),
        r2: sys.rho[1].clone(),
        i1: sys.inertia[0].clone(),
        i2: sys.inertia[1].clone(),
        g: sys.g.clone(),
    }
}

fn close(a: &Float, b: &Float, scale: &Float, bits: i32, what: &str) {
    let d = Float::with_val(a.prec(), a - b).abs();
    let tol = Float::with_val(a.prec(), scale.clone().abs() + 1u32) >> bits;
    assert!(d <= tol, "{what}: {a} vs {b} (diff {:e})", d.to_f64());
}

/// The generalised n-cylinder KKT solve at n = 2 equals the two-cylinder
/// one of `mechanics::kkt` (written separately, from the paper's eq. 98) for
/// every contact model, including off-vertical velocities.
#[test]
fn stack_kkt_equals_two_cylinder_kkt() {
    let prec = 300;
    let mut a = Params::identical_solid();
    a.m1 = q("3");
    a.m2 = q("1.25");
    a.r1 = q("0.7");
    a.r2 = q("1/3");
    a.k1 = q("0.4");
    a.k2 = q("0.9");
    a.g = q("9.81");
    for floor in [Floor::Roll, Floor::Slip, Floor::Fixed] {
        for contact in [Contact::Roll, Contact::Slip] {
            let w0 = if floor == Floor::Fixed { "0" } else { "-0.7" };
            let start = Start {
                theta0: Exact::parse("t", "0.3", false).unwrap(),
                thetadot0: q("0.45"),
                omega0: q(w0),
            };
            let m = Ideal::new(a.clone(), floor, contact, start).unwrap();
            let sm = StackModel::from_model(&m);
            let mut sys = System::new(&sm, prec).unwrap();
            let (q0, v0) = sys.initial_state(&sm).unwrap();
            let acc = sys.accel(&q0, &v0).unwrap();
            let k = kkt::solve(
                &bodies(&sys),
                floor,
                contact,
                &q0[system::th(0)],
                &v0[system::th(0)],
            )
            .unwrap();
            let what = format!("{floor:?}/{contact:?}");
            let scale = Float::with_val(prec, 20u32);
            for i in 0..6 {
                close(
                    &acc.qdd[i],
                    &k.qdd[i],
                    &scale,
                    prec as i32 - 20,
                    &format!("qdd[{i}] {what}"),
                );
            }
            let lam = |row: Row| {
                sys.rows
                    .iter()
                    .position(|r| *r == row)
                    .map(|i| acc.lambda[i].clone())
                    .unwrap_or_else(|| Float::new(prec))
            };
            close(
                &lam(Row::FloorFriction),
                &k.f1,
                &scale,
                prec as i32 - 20,
                &format!("F1 {what}"),
            );
            close(
                &lam(Row::FloorNormal),
                &k.n1,
                &scale,
                prec as i32 - 20,
                &format!("N1 {what}"),
            );
            close(
                &lam(Row::Friction(0)),
                &k.f21,
                &scale,
                prec as i32 - 20,
                &format!("F21 {what}"),
            );
            close(
                &lam(Row::Normal(0)),
                &k.n12,
                &scale,
                prec as i32 - 20,
                &format!("N12 {what}"),
            );
            close(
                &lam(Row::Hold),
                &k.hold,
                &scale,
                prec as i32 - 20,
                &format!("hold {what}"),
            );
        }
    }
}

/// Newton–Euler for every body of a stack: the multipliers are the contact
/// forces. m_i a_i = Σ forces and I_i α_i = Σ torques for each cylinder of
/// n = 3 and n = 4 stacks with mixed contact models, at a state in motion.
#[test]
fn stack_multipliers_satisfy_newton_euler() {
    let prec = 256;
    for text in [
        "n=3;theta0=0.2,-0.3;thetadot0=0.4,-0.1;omega0=0.3;m=1,2,0.5;r=1,0.5,0.8;k=0.5,0.4,1.5",
        "n=4;floor=slip;contacts=roll,slip,roll;theta0=0.1,0.4,-0.2;thetadot0=0.3,0.2,-0.5;omega0=-0.2;m=2,1,1.5,0.7;r=1,0.6,0.9,0.4;k=0.5,0.3,0.8,0.5;g=9.81",
        "n=3;floor=fixed;contacts=slip,roll;theta0=0.3,0.1;thetadot0=0.2,0.6",
    ] {
        let sp = spec::parse(text).unwrap();
        let sm = &sp.model;
        let n = sm.n();
        let mut sys = System::new(sm, prec).unwrap();
        let (q0, v0) = sys.initial_state(sm).unwrap();
        let acc = sys.accel(&q0, &v0).unwrap();
        let lam = |row: Row| {
            sys.rows
                .iter()
                .position(|r| *r == row)
                .map(|i| acc.lambda[i].clone())
                .unwrap_or_else(|| Float::new(prec))
        };
        let f = |x: &Float| Float::with_val(prec, x);
        // centre accelerations (ṙ = r̈ = 0 on the manifold)
        let mut ax = vec![f(&acc.qdd[system::X1])];
        let mut ay = vec![f(&acc.qdd[system::Y1])];
        for j in 0..n - 1 {
            let th = &q0[system::th(j)];
            let (s, c) = th.clone().sin_cos(Float::new(prec));
            let r = &q0[system::rr(j)];
            let td = &v0[system::th(j)];
            let tdd = &acc.qdd[system::th(j)];
            let td2 = Float::with_val(prec, td * td);
            let x = Float::with_val(prec, &ax[j] + Float::with_val(prec, r * tdd) * &c)
                - Float::with_val(prec, r * &td2) * &s;
            let y = Float::with_val(prec, &ay[j] - Float::with_val(prec, r * tdd) * &s)
                - Float::with_val(prec, r * &td2) * &c;
            ax.push(x);
            ay.push(y);
        }
        // forces and torques (counter-clockwise) on each body
        let mut fx = vec![Float::new(prec); n];
        let mut fy: Vec<Float> = (0..n)
            .map(|i| -Float::with_val(prec, &sys.m[i] * &sys.g))
            .collect();
        let mut tau = vec![Float::new(prec); n];
        fx[0] += lam(Row::FloorFriction);
        fy[0] += lam(Row::FloorNormal);
        // a floor's friction acts at the contact point; a holder's force
        // (fixed floor) at the axis, with its own torque
        if sm.floor == Floor::Roll {
            tau[0] += Float::with_val(prec, &sys.rho[0] * lam(Row::FloorFriction));
        }
        tau[0] -= lam(Row::Hold);
        for j in 0..n - 1 {
            let (s, c) = q0[system::th(j)].clone().sin_cos(Float::new(prec));
            let nn = lam(Row::Normal(j));
            let ff = lam(Row::Friction(j));
            let gx = Float::with_val(prec, &nn * &s) + Float::with_val(prec, &ff * &c);
            let gy = Float::with_val(prec, &nn * &c) - Float::with_val(prec, &ff * &s);
            fx[j + 1] += &gx;
            fy[j + 1] += &gy;
            fx[j] -= &gx;
            fy[j] -= &gy;
            tau[j + 1] += Float::with_val(prec, &sys.rho[j + 1] * &ff);
            tau[j] += Float::with_val(prec, &sys.rho[j] * &ff);
        }
        let scale = Float::with_val(prec, 100u32);
        for i in 0..n {
            let what = format!("{text}: body {}", i + 1);
            close(&Float::with_val(prec, &sys.m[i] * &ax[i]), &fx[i], &scale, prec as i32 - 24, &format!("{what} x"));
            close(&Float::with_val(prec, &sys.m[i] * &ay[i]), &fy[i], &scale, prec as i32 - 24, &format!("{what} y"));
            let alpha = if i == 0 {
                -acc.qdd[system::PHI1].clone()
            } else {
                acc.qdd[system::psi(i - 1)].clone()
            };
            close(&Float::with_val(prec, &sys.inertia[i] * &alpha), &tau[i], &scale, prec as i32 - 24, &format!("{what} torque"));
        }
    }
}

/// A two-cylinder stack given as a SPEC is the first route's model:
/// separation angle and time, and the forces there, to 30 digits.
#[test]
fn stack_of_two_equals_first_route() {
    let digits = 30;
    for (text, floor, contact) in [
        (
            "n=2;theta0=0.1;m=3,1.25;r=0.7,1/3;k=0.4,0.9;g=9.81",
            Floor::Roll,
            Contact::Roll,
        ),
        (
            "n=2;floor=slip;contacts=roll;theta0=0.2;thetadot0=0.3;omega0=-0.7",
            Floor::Slip,
            Contact::Roll,
        ),
    ] {
        let sp = spec::parse(text).unwrap();
        let sm = &sp.model;
        let params = Params {
            m1: sm.m[0].clone(),
            m2: sm.m[1].clone(),
            r1: sm.r[0].clone(),
            r2: sm.r[1].clone(),
            k1: sm.k[0].clone(),
            k2: sm.k[1].clone(),
            g: sm.g.clone(),
        };
        let start = Start {
            theta0: sm.theta0[0].clone(),
            thetadot0: sm.thetadot0[0].clone(),
            omega0: sm.omega0.clone(),
        };
        let model = Ideal::new(params, floor, contact, start).unwrap();
        let mut o = Oracle::new(&model, digits).unwrap();
        let sep = o.separation().unwrap();
        let prec = bits_for_digits(digits) + 40;
        let sol = solve_stack(&sp, prec, &[]).unwrap();
        let open = sol.opening.as_ref().expect("a contact opens");
        assert_eq!(open.which, "N12", "{text}");
        let tol = ten_pow(prec, -(digits as i32));
        let rel = |a: &Float, b: &Float, what: &str| {
            let d = Float::with_val(prec, a - b).abs() / Float::with_val(prec, b.abs_ref());
            assert!(d < tol, "{text} {what}: {a} vs {b}");
        };
        rel(&open.at.q[system::th(0)], &sep.theta_s.value, "theta_s");
        rel(&open.at.t, &sep.t_s.as_ref().unwrap().value, "t_s");
        let f21 = sep.extra.iter().find(|v| v.name == "F21_at_s").unwrap();
        let i = sol.row_names.iter().position(|r| r == "F21").unwrap();
        rel(&open.at.lambda[i], &f21.value, "F21 at separation");
    }
}

/// Footnote 3 for n = 3: energy and the one canonical momentum (conjugate
/// to φ1, rolling floor and contacts) are conserved along the motion to the
/// requested precision; with a frictionless floor both x-momentum and the
/// spin momentum are.
#[test]
fn stack_of_three_conserves_energy_and_momentum() {
    let digits = 30;
    for (text, nmom) in [
        (
            "n=3;theta0=0.1,0.05;thetadot0=0.1,-0.2;omega0=0.4;m=1,2,1;r=1,0.5,0.75;k=0.5,0.4,0.9",
            1,
        ),
        (
            "n=3;floor=slip;contacts=roll,roll;theta0=0.1,0.05;omega0=0.2",
            2,
        ),
    ] {
        let sp = spec::parse(text).unwrap();
        let prec = bits_for_digits(digits) + 24;
        let times: Vec<Float> = ["0.5", "1", "1.5", "2"]
            .iter()
            .map(|t| Float::with_val(prec, &q(t)))
            .collect();
        let sol = solve_stack(&sp, prec, &times).unwrap();
        assert_eq!(sol.p0.len(), nmom, "{text}");
        let bound = ten_pow(64, -(digits as i32));
        assert!(
            sol.energy_drift < bound,
            "{text}: energy {:e}",
            sol.energy_drift.to_f64()
        );
        assert!(
            sol.momentum_drift < bound,
            "{text}: momentum {:e}",
            sol.momentum_drift.to_f64()
        );
        assert!(
            sol.run.max_drift < bound,
            "{text}: constraint drift {:e}",
            sol.run.max_drift.to_f64()
        );
        // the samples were really taken along the motion
        let reached = sol.run.outputs.len();
        assert!(reached >= 2, "{text}: {reached} samples");
        let mut sys = System::new(&sp.model, sol.work_prec).unwrap();
        let s: &Sample = &sol.run.outputs[reached - 1];
        let e = sys.energy(&s.q, &s.v);
        let d = Float::with_val(prec, &e - &sol.e0).abs();
        assert!(
            d < bound,
            "{text}: energy at the last sample {:e}",
            d.to_f64()
        );
    }
}

/// Which contact opens first for n = 3 and n = 4, verified at two
/// precisions (the report's ladder) and the same at 20 and 30 digits.
#[test]
fn stacks_of_three_and_four_open_a_contact() {
    for (text, which) in [
        (
            "n=3;floor=roll;m=1,1,1;r=1,1,1;k=1/2,1/2,1/2;theta0=0.1,0.05;contacts=roll,roll",
            "N23",
        ),
        ("n=4;theta0=0.1,0.05,0.02", "N34"),
    ] {
        let a = stack_report(text, 30, false).unwrap();
        let b = stack_report(text, 20, true).unwrap();
        assert!(a.contains(&format!("first_opening = {which}")), "{a}");
        let line = |key: &str| {
            a.lines()
                .find(|l| l.starts_with(key) && l[key.len()..].trim_start().starts_with('='))
                .unwrap_or_else(|| panic!("{key} in {a}"))
                .to_string()
        };
        let t30 = line("t_open");
        assert!(t30.contains("[30 digits"), "{t30}");
        let v30 = t30
            .split('=')
            .nth(1)
            .unwrap()
            .split_whitespace()
            .next()
            .unwrap()
            .to_string();
        let json: serde_json::Value = serde_json::from_str(&b).unwrap();
        assert_eq!(json["first_opening"], which, "{b}");
        let v20 = json["t_open"].as_str().unwrap();
        let x30 = Float::with_val(200, Float::parse(&v30).unwrap());
        let x20 = Float::with_val(200, Float::parse(v20).unwrap());
        let d = Float::with_val(200, &x30 - &x20).abs() / &x30;
        assert!(d < 1e-19, "{text}: {v30} vs {v20}");
        assert!(json["theta1"].is_string() && json["digits_verified"]["t_open"] == "20");
    }
}

/// A stack in other units is the same motion: at g = 10^-60 … 10^60 the
/// three-cylinder stack opens the same contact at the unit stack's θ, at a
/// time scaled by 10^(-k/2), verified at the first rung with the same
/// digits and no projection (the finite-difference rate of a multiplier, the
/// event time's tolerance and the constraint drift in seconds and metres,
/// not in the stack's units, made g = 10^40 fail to verify the opening and
/// g = 10^60 find another contact open first).
#[test]
fn a_stack_in_other_units_is_the_same_motion() {
    let field = |rep: &str, key: &str| -> (String, String) {
        let l = rep
            .lines()
            .find(|l| l.starts_with(key) && l[key.len()..].trim_start().starts_with('='))
            .unwrap_or_else(|| panic!("{key} in {rep}"))
            .to_string();
        let v = l.split('=').nth(1).unwrap().trim().to_string();
        let mut it = v.split_whitespace();
        let num = it.next().unwrap().to_string();
        let mant: String = num
            .split(['e', 'E'])
            .next()
            .unwrap()
            .chars()
            .filter(char::is_ascii_digit)
            .collect::<String>()
            .trim_start_matches('0')
            .to_string();
        (mant, it.collect::<Vec<_>>().join(" "))
    };
    let unit = stack_report("n=3;theta0=0.1,0.05", 30, false).unwrap();
    for g in ["1e-60", "1e40", "1e60"] {
        let rep = stack_report(&format!("n=3;theta0=0.1,0.05;g={g}"), 30, false).unwrap();
        assert!(rep.contains("first_opening = N23"), "g = {g}: {rep}");
        assert!(rep.contains("(0 projections)"), "g = {g}: {rep}");
        for key in ["t_open", "theta1"] {
            let (mu, du) = field(&unit, key);
            let (mg, dg) = field(&rep, key);
            assert_eq!(mg, mu, "g = {g}: {key}");
            assert_eq!(
                dg.split(';').next(),
                du.split(';').next(),
                "g = {g}: {key} digits"
            );
        }
    }
}

/// A turning point θ̇ = 0 is located to full precision: a two-cylinder
/// stack thrown towards the top (θ̇0 < 0) stops where energy says,
/// (g/r) cos θt = K(θ0) θ̇0²/2 + (g/r) cos θ0 with K = 1 + k2 − A(cos θ − k2)²
/// (paper eq. 22, ω0 = 0), and falls back.
#[test]
fn turning_point_matches_energy() {
    let digits = 30;
    let sp = spec::parse("n=2;theta0=0.3;thetadot0=-0.1").unwrap();
    let prec = bits_for_digits(digits) + 24;
    let sol = solve_stack(&sp, prec, &[]).unwrap();
    assert_eq!(sol.turning.len(), 1, "one turning point");
    let (j, at, _) = &sol.turning[0];
    assert_eq!(*j, 0);
    // identical solid cylinders, g = r1 = r2 = 1: A = 1/3, r = 2, k2 = 1/2
    let p = prec;
    let th0 = Float::with_val(p, &q("0.3"));
    let c0 = Float::with_val(p, th0.cos_ref());
    let k0 = Float::with_val(p, 1.5) - Float::with_val(p, &c0 - 0.5f64).square() / 3u32;
    let td0 = Float::with_val(p, &q("-0.1"));
    let gr = Float::with_val(p, 0.5);
    let ct = (Float::with_val(p, &k0 * &td0) * &td0 / 2u32 + Float::with_val(p, &gr * &c0)) / &gr;
    let th_t = ct.acos();
    let d = Float::with_val(p, &at.q[system::th(0)] - &th_t).abs();
    assert!(
        d < ten_pow(64, -(digits as i32)),
        "theta at turning {} vs {}",
        at.q[system::th(0)],
        th_t
    );
    assert!(sol.opening.is_some(), "it falls back and separates");
}

/// The SPEC help text documents every key; bad SPECs name the key.
#[test]
fn stack_spec_help_and_errors() {
    let h = stack_report("help", 30, false).unwrap();
    for key in [
        "n ",
        "floor",
        "contacts",
        "theta0",
        "thetadot0",
        "omega0",
        "tmax",
    ] {
        assert!(h.contains(key), "{key} missing from help");
    }
    match stack_report("n=3;theta0=0.1,0.2,0.3", 30, false) {
        Err(cylroll::Error::InvalidParameter { name, .. }) => assert_eq!(name, "theta0"),
        other => panic!("{other:?}"),
    }
    match stack_report("n=2;theta0=0", 30, false) {
        Err(e) => assert_eq!(e.exit_code(), 2),
        Ok(s) => panic!("{s}"),
    }
}

/// Heavier: the routes agree to 100 digits on three cases.
#[test]
#[ignore = "about 10 s of CPU (longer under load): run with --ignored"]
fn routes_agree_at_100_digits() {
    let digits = 100;
    for case in cases()
        .iter()
        .filter(|c| ["roll-roll", "bobbin", "moving-slip"].contains(&c.name.as_str()))
    {
        let rep = compare_case(case, digits).unwrap();
        assert_routes_agree(&case.name, &rep, digits);
    }
}

/// Every number in golden/data (scalars and every grid cell of every case)
/// is reproduced by the second route to all its printed digits.
#[test]
fn golden_data_is_reproduced_by_route_2() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("golden/data");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .expect("golden/data")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    files.sort();
    assert!(files.len() >= 10, "{} golden files", files.len());
    let mut total = 0;
    for f in &files {
        let text = std::fs::read_to_string(f).unwrap();
        let g = golden::check_golden(&text, 0).unwrap_or_else(|e| panic!("{}: {e}", f.display()));
        let v: serde_json::Value = serde_json::from_str(&text).unwrap();
        assert_eq!(v["schema"], "cylroll-golden/2", "{}", f.display());
        if v["model"]["floor"] == "coulomb" || v["model"]["contact"] == "coulomb" {
            // friction cases are computed by route 2's integrators themselves
            // (tests/friction.rs holds them against an independent derivation)
            assert_eq!(g.checked, 0, "{}", g.case);
            continue;
        }
        assert!(
            g.failures.is_empty(),
            "{}: {:?}",
            g.case,
            &g.failures[..g.failures.len().min(5)]
        );
        assert!(g.checked > 400, "{}: {} values", g.case, g.checked);
        total += g.checked;
    }
    assert!(total > 4000, "{total}");
}

/// Cylinders without inertia (k = 0) on frictionless contacts: their free
/// rates keep the reference value (the first route's convention), and both
/// routes agree, also for the combined direction of a frictionless floor
/// under k1 = k2 = 0 with a rolling contact.
#[test]
fn massless_spins_agree_with_first_route() {
    let digits = 30;
    for (floor, contact, k1, k2) in [
        (Floor::Slip, Contact::Slip, "0", "0"),
        (Floor::Slip, Contact::Roll, "0", "0"),
        (Floor::Roll, Contact::Slip, "0.5", "0"),
    ] {
        let mut p = Params::identical_solid();
        p.k1 = q(k1);
        p.k2 = q(k2);
        let start = Start {
            theta0: Exact::parse("t", "0.1", false).unwrap(),
            thetadot0: q("0.2"),
            omega0: q("0.3"),
        };
        let m = Ideal::new(p, floor, contact, start).unwrap();
        let case = VerifyCase {
            name: format!("{floor}-{contact} k1={k1} k2={k2}"),
            model: m,
        };
        let rep = compare_case(&case, digits).unwrap();
        assert_routes_agree(&case.name, &rep, digits);
    }
}

/// The projection back onto the constraint manifold (used only if drift
/// ever exceeds its threshold): a perturbed state of a mixed stack is put
/// back with zero residuals, its independent coordinates unchanged.
#[test]
fn projection_restores_the_constraints() {
    let prec = 200;
    let sp = spec::parse(
        "n=3;floor=roll;contacts=roll,slip;theta0=0.2,-0.1;thetadot0=0.3,0.1;omega0=0.5",
    )
    .unwrap();
    let mut sys = System::new(&sp.model, prec).unwrap();
    let (q0, v0) = sys.initial_state(&sp.model).unwrap();
    assert!(sys.drift(&q0, &v0, &q0).is_zero());
    let mut q = q0.clone();
    let mut v = v0.clone();
    for (i, x) in q.iter_mut().enumerate() {
        *x += Float::with_val(prec, 1e-20) * (i as u32 + 1);
    }
    for (i, x) in v.iter_mut().enumerate() {
        *x -= Float::with_val(prec, 1e-20) * (i as u32 + 2);
    }
    assert!(sys.drift(&q, &v, &q0) > 1e-21);
    let theta = q[system::th(1)].clone();
    sys.project(&mut q, &mut v, &q0);
    let d = sys.drift(&q, &v, &q0);
    assert!(
        d < ten_pow(64, -55),
        "drift after projection {:e}",
        d.to_f64()
    );
    assert_eq!(q[system::th(1)], theta);
}

/// The second route's conservation checks in any units: the two-cylinder
/// run of the paper's model at g = 10^-40 and 10^40 reports the energy and
/// momentum drifts of g = 1 (each relative to the motion's own sizes,
/// Σ m ρ g and Σ m ρ · ρ0/ts): the momentum drift was absolute, 10^20 times
/// the unit model's at g = 10^40, and the energy's scale |E0| + m2 g a
/// force, not an energy.
#[test]
fn the_second_route_s_drifts_are_relative_in_any_units() {
    let prec = 160;
    let drifts = |k: i32| {
        let mut p = Params::identical_solid();
        let n = Rational::from(rug::Integer::from(10u32).pow(k.unsigned_abs()));
        p.g = if k >= 0 { n } else { n.recip() };
        let ts = Float::with_val(prec, Float::with_val(prec, &p.r()) / &p.g).sqrt();
        let start = Start::rest(Exact::parse("theta0", "1/10", false).unwrap());
        let m = Ideal::new(p, Floor::Roll, Contact::Roll, start).unwrap();
        let opts = TwoOpts {
            phi1_events: false,
            reach: Vec::new(),
        };
        let t_end = Float::with_val(prec, &ts * 20u32);
        let run = two_cylinder(&m, prec, &[], &t_end, &opts).unwrap();
        (run.energy_drift.to_f64(), run.momentum_drift.to_f64())
    };
    let (e0, p0) = drifts(0);
    assert!(e0 < 1e-30 && p0 < 1e-30, "g = 1: {e0:e} {p0:e}");
    for k in [-40, 40] {
        let (e, p) = drifts(k);
        // the same motion in another time unit: the same relative drifts,
        // up to the rounding of a different run
        for (x, x0, what) in [(e, e0, "energy"), (p, p0, "momentum")] {
            assert!(
                x < 1e-30 && x <= 100.0 * x0.max(1e-40),
                "g = 1e{k}: {what} {x:e} against {x0:e}"
            );
        }
    }
}
