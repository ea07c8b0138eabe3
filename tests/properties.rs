//! Property tests: invariants over random valid models, and no panic over a
//! hostile argument space of the command line.

use cylroll::exact::Exact;
use cylroll::mechanics::dynamics::Dyn;
use cylroll::mechanics::Reduced;
use cylroll::model::{Contact, Floor, Ideal, Law, Model, Params, Start};
use cylroll::oracle::Oracle;
use cylroll::Error;
use proptest::prelude::*;
use proptest::test_runner::RngSeed;

/// A fixed seed: the same cases on every run (CI is reproducible); change it
/// to explore new ones, and keep what they find as explicit regression tests.
const SEED: u64 = 0x5eed_c71e_0001;
use rug::{Float, Rational};

fn rat(n: i64, d: i64) -> Rational {
    Rational::from((n, d))
}

prop_compose! {
    fn any_model()(
        m1 in 1i64..60, m2 in 1i64..60, r1 in 1i64..30, r2 in 1i64..30,
        k1 in 0i64..30, k2 in 0i64..30, si in any::<bool>(),
        floor in 0usize..3, contact in 0usize..2,
        th0 in 1i64..40, td0 in 0i64..4, w0 in -5i64..5,
    ) -> Ideal {
        let params = Params {
            m1: rat(m1, 10), m2: rat(m2, 10), r1: rat(r1, 10), r2: rat(r2, 10),
            k1: rat(k1, 10), k2: rat(k2, 10),
            g: if si { rat(981, 100) } else { rat(1, 1) },
        };
        let floor = [Floor::Roll, Floor::Slip, Floor::Fixed][floor];
        let contact = [Contact::Roll, Contact::Slip][contact];
        let start = Start {
            theta0: Exact::rational(rat(th0, 100)),
            thetadot0: rat(td0, 20),
            omega0: if floor == Floor::Fixed { rat(0, 1) } else { rat(w0, 4) },
        };
        Ideal::new(params, floor, contact, start).expect("valid by construction")
    }
}

fn num(v: &cylroll::numeric::verify::Verified) -> f64 {
    v.text.parse().unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, rng_seed: RngSeed::Fixed(SEED), .. ProptestConfig::default() })]

    #[test]
    fn invariants_of_the_motion(model in any_model()) {
        let mut o = match Oracle::new(&model, 20) {
            Ok(o) => o,
            // a start where the cylinders already part is refused, not computed
            Err(Error::NotPhysical { .. }) => return Ok(()),
            Err(e) => panic!("{e}: {}", model.describe()),
        };
        let sep = match o.separation() {
            Ok(s) => s,
            Err(Error::NotPhysical { .. }) => return Ok(()), // e.g. never separates before pi
            Err(e) => panic!("{e}: {}", model.describe()),
        };
        let th0 = model.start().theta0.to_f64();
        let ths = num(&sep.theta_s);
        prop_assert!(ths > th0, "{}", model.describe());
        let lifts = sep.extra.iter().any(|v| v.name == "theta_N1_zero");
        // the motion ends at θs, or before it where cylinder 2, still on
        // cylinder 1, lands on the floor: cos θ = (r2 − r1)/(r1 + r2)
        let pr = model.params();
        let (r1, r2) = (pr.r1.to_f64(), pr.r2.to_f64());
        let end = if r2 > r1 { ths.min(((r2 - r1) / (r1 + r2)).acos()) } else { ths };
        let mut last_t = 0.0;
        for frac in [0.25, 0.5, 0.9] {
            let th = th0 + frac * (end - th0);
            let e = Exact::parse("theta", &format!("{th:.12}"), false).unwrap();
            let f = o.forces_at(&e).unwrap();
            let n12 = num(&f[3]);
            prop_assert!(n12 > 0.0, "N12 = {n12} at {th}: {}", model.describe());
            if !lifts {
                prop_assert!(num(&f[1]) > 0.0, "N1 at {th}: {}", model.describe());
            }
            let t = num(&o.time_at(&e).unwrap());
            prop_assert!(t > last_t, "t(theta) increasing: {}", model.describe());
            last_t = t;
        }
        // same answer at two requested precisions
        let mut o2 = Oracle::new(&model, 32).unwrap();
        let s2 = o2.separation().unwrap();
        prop_assert_eq!(
            cylroll::numeric::decimal::to_sig(&s2.theta_s.value, 20),
            sep.theta_s.text.clone()
        );
        // energy and the canonical momenta are constant along the motion
        let red = Reduced::new(&model).unwrap();
        let d = Dyn::new(&model, &red, 200).unwrap();
        let s0 = d.state(&Float::new(200));
        let e0 = d.energy(&s0);
        let p0 = d.momenta(&s0);
        let st = d.state(&Float::with_val(200, (ths - th0) * 0.7));
        let de = Float::with_val(200, d.energy(&st) - &e0).abs().to_f64();
        prop_assert!(de <= 1e-50 * (1.0 + e0.to_f64().abs()), "energy drift {de}");
        for (a, b) in d.momenta(&st).iter().zip(&p0) {
            let dp = Float::with_val(200, a - b).abs().to_f64();
            prop_assert!(dp <= 1e-50 * (1.0 + b.to_f64().abs()), "momentum drift {dp}");
        }
    }
}

fn token() -> impl Strategy<Value = String> {
    prop_oneof![
        Just("--m1".to_string()),
        Just("--k2".to_string()),
        Just("--theta0".to_string()),
        Just("--thetadot0".to_string()),
        Just("--omega0".to_string()),
        Just("--floor".to_string()),
        Just("--contact".to_string()),
        Just("--digits".to_string()),
        Just("--format".to_string()),
        Just("--to".to_string()),
        Just("--theta".to_string()),
        Just("--times".to_string()),
        Just("--mu".to_string()),
        Just("--mu-floor".to_string()),
        Just("--mu-contact".to_string()),
        Just("--branch".to_string()),
        Just("part".to_string()),
        Just("--part-at".to_string()),
        Just("0.3,0.1".to_string()),
        Just("0.1,0.3".to_string()),
        Just("--params".to_string()),
        Just("0".to_string()),
        Just("-1".to_string()),
        Just("1/0".to_string()),
        Just("nan".to_string()),
        Just("inf".to_string()),
        Just("1e999999".to_string()),
        Just("pi/2".to_string()),
        Just("0.1".to_string()),
        Just("slip".to_string()),
        Just("fixed".to_string()),
        Just("json".to_string()),
        Just("".to_string()),
        Just("99999".to_string()),
        Just("3".to_string()),
        Just("0,1,2".to_string()),
        Just("1e-30".to_string()),
        "[ -~]{0,12}",
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, rng_seed: RngSeed::Fixed(SEED), .. ProptestConfig::default() })]

    #[test]
    fn the_command_line_never_panics(
        sub in prop_oneof![Just("separation"), Just("time"), Just("forces"), Just("trajectory")],
        args in proptest::collection::vec(token(), 0..7),
    ) {
        let out = assert_cmd::Command::cargo_bin("cylroll").unwrap()
            .arg(sub).args(&args)
            .timeout(std::time::Duration::from_secs(60))
            .output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        prop_assert!(!err.contains("panicked"), "{sub} {args:?}: {err}");
        let code = out.status.code();
        prop_assert!(matches!(code, Some(0) | Some(2) | Some(3)), "{sub} {args:?}: {code:?} {err}");
        if code != Some(0) {
            prop_assert!(out.stdout.is_empty(), "partial output on error: {sub} {args:?}");
            prop_assert!(!err.trim().is_empty());
        }
    }
}

prop_compose! {
    fn any_friction_model()(
        m1 in 1i64..40, m2 in 1i64..40, r1 in 2i64..30, r2 in 2i64..30,
        k1 in 1i64..20, k2 in 1i64..20,
        th0 in 3i64..40, mf in 0usize..6, mc in 0usize..6, ks in any::<bool>(),
    ) -> Model {
        let params = Params {
            m1: rat(m1, 10), m2: rat(m2, 10), r1: rat(r1, 10), r2: rat(r2, 10),
            k1: rat(k1, 10), k2: rat(k2, 10), g: rat(1, 1),
        };
        let mus = ["0.05", "0.2", "0.5", "1", "3", "inf"];
        let law = |i: usize| {
            let t = if ks && mus[i] != "inf" { format!("{0},{0}", mus[i]) } else { mus[i].to_string() };
            Law::parse_mu("mu", &t).unwrap()
        };
        Model::new(params, law(mf), law(mc), Start::rest(Exact::rational(rat(th0, 100))))
            .expect("valid by construction")
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, rng_seed: RngSeed::Fixed(SEED), .. ProptestConfig::default() })]

    /// Over random models with Coulomb friction: events in time order, the
    /// dissipated work never decreasing from event to event, the energy
    /// balance kept, separation after the start and the impact after
    /// separation (or a lift-off ending the model); an undecidable mode
    /// (exit 3) or a start that parts at once are refusals, not numbers.
    #[test]
    fn invariants_of_the_motion_with_friction(model in any_friction_model()) {
        use cylroll::motion::{self, End, Kind};
        let req = motion::Request {
            times: Vec::new(),
            until: motion::Until::End,
            theta_only: false,
            branch: motion::Branch::Stay,
            method: motion::Method::Auto,
            horizon: None,
            run: cylroll::numeric::verify::Run::High,
            digits: 0,
            sides: Vec::new(),
            target_side: None,
            low_deltas: Vec::new(),
            derived_at_high: false,
        };
        let m = match motion::run(&model, &req, 120, &mut motion::Caches::default()) {
            Ok(m) => m,
            Err(Error::NotConverged { quantity, .. }) if quantity == "mode" || quantity == "separation" => return Ok(()),
            Err(Error::NotPhysical { .. }) => return Ok(()),
            Err(e) => panic!("{e}: {}", model.describe()),
        };
        prop_assert!(m.energy_drift.to_f64() < 1e-25, "{}", m.energy_drift.to_f64());
        let mut t = 0.0f64;
        let mut w = 0.0f64;
        for e in &m.events {
            let te = e.at.t.to_f64();
            prop_assert!(te >= t, "events out of order");
            t = te;
            let we = e.at.work.to_f64();
            prop_assert!(we >= w - 1e-30, "work decreases");
            w = we;
        }
        if m.end == Some(End::LiftOff) {
            // cylinder 1 leaves the floor: N1 = 0 there, the model ends
            let last = m.events.last().unwrap();
            prop_assert_eq!(last.kind, Kind::LiftOff);
            prop_assert!(last.at.n1.to_f64().abs() < 1e-20, "N1 at lift-off {}", last.at.n1.to_f64());
            return Ok(());
        }
        prop_assert_eq!(m.events.last().map(|e| e.kind), Some(Kind::Impact));
        let imp = m.impact.as_ref().unwrap();
        let Some(sep) = m.separation.as_ref() else {
            // cylinder 2 landed on the floor while still on cylinder 1
            prop_assert!((imp.y2.to_f64() - model.params().r2.to_f64()).abs() < 1e-12);
            return Ok(());
        };
        prop_assert!(sep.theta.to_f64() > model.start().theta0.to_f64());
        prop_assert!(sep.n12.to_f64() >= -1e-20);
        prop_assert!(imp.t > sep.t);
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, rng_seed: RngSeed::Fixed(SEED), .. ProptestConfig::default() })]

    /// The high-precision routes against the low-precision ones on random
    /// models: at 40 digits t(θ), t_s and θ(t) come from tanh-sinh and the
    /// Taylor run (both working precisions below 256 bits), at 190 digits
    /// from Chebyshev interpolation and its inversion (both above 600 bits);
    /// the first 40 digits must agree.
    #[test]
    fn chebyshev_and_tanh_sinh_routes_agree(model in any_model()) {
        let (mut lo, mut hi) = match (Oracle::new(&model, 40), Oracle::new(&model, 190)) {
            (Ok(a), Ok(b)) => (a, b),
            _ => return Ok(()),
        };
        let sep = match lo.separation() {
            Ok(s) => s,
            Err(Error::NotPhysical { .. }) => return Ok(()),
            Err(e) => panic!("{e}: {}", model.describe()),
        };
        let round = |v: &cylroll::numeric::verify::Verified, d: u32| {
            cylroll::numeric::decimal::to_sig(&v.value, d)
        };
        let th0 = model.start().theta0.to_f64();
        let ths = num(&sep.theta_s);
        // an angle inside the half-angle form's range (θ ≤ 2π/3)
        let th = th0 + 0.6 * (ths.min(2.0) - th0);
        let e = Exact::parse("theta", &format!("{th:.12}"), false).unwrap();
        let a = lo.time_at(&e).unwrap();
        let b = hi.time_at(&e).unwrap();
        prop_assert_eq!(round(&b, a.digits), a.text.clone(), "t: {}", model.describe());
        // θ(t) at that time, by the Taylor run and by the inversion
        let t = Exact::parse("t", &format!("{:.12}", num(&a)), false).unwrap();
        let ra = lo.theta_at_times(std::slice::from_ref(&t)).unwrap();
        let rb = hi.theta_at_times(std::slice::from_ref(&t)).unwrap();
        prop_assert_eq!(round(&rb[0], ra[0].digits), ra[0].text.clone(), "theta(t): {}", model.describe());
        if ths < 2.0 {
            let sb = hi.separation().unwrap();
            if let (Some(x), Some(y)) = (&sep.t_s, &sb.t_s) {
                prop_assert_eq!(round(y, x.digits), x.text.clone(), "t_s: {}", model.describe());
            }
        }
    }
}
