//! The branch point of the rigid-body model (`tests/fixtures/branch_derivation.md`) seen by
//! two regularisations of the contacts, simulated in `f64` without the cylroll library
//! (`tests/support/branch_sim.rs`), started from the closed rigid motion a little before the
//! branch point θ* (the `pre_*` state of `tests/fixtures/branch_independent.toml`, computed
//! by `tests/fixtures/branch_independent.py`).
//!
//! From θ* on, the rigid model with rolling contacts has two consistent continuations: stay
//! closed (N12 > 0) or part (N12 = F21 = 0). A stiff compliant contact stays closed and
//! parts where the closed branch ends. A velocity-level complementarity stepper solved by
//! projected Gauss–Seidel from zero impulses parts as soon as parting is admissible, at θ*;
//! warm-started from the previous step's impulses, the contact kept through its small
//! positive gaps, the same stepper follows the closed branch instead: which solution of the
//! step's complementarity problem is taken is the solver's choice. The tolerances are the
//! observed errors of each sequence with a margin (observed values in the comments).

#[path = "support/branch_sim.rs"]
mod branch_sim;

use branch_sim::{run_compliant, run_stepper, Compliant, Params, RigidState, Solver};

const FIXTURE: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/tests/fixtures/branch_independent.toml"
);

/// One case of the fixture: the model, the pre-branch state and the rigid angles.
struct Case {
    p: Params,
    start: RigidState,
    t_pre: f64,
    theta_star: f64,
    theta_dot_star: f64,
    n12_star: f64,
    theta_s: f64,
    t_s: f64,
}

fn number(text: &str) -> f64 {
    match text.split_once('/') {
        Some((a, b)) => a.trim().parse::<f64>().unwrap() / b.trim().parse::<f64>().unwrap(),
        None => text.trim().parse().unwrap(),
    }
}

fn case(name: &str) -> Case {
    let all: toml::Table = toml::from_str(&std::fs::read_to_string(FIXTURE).unwrap()).unwrap();
    let t = all
        .get(name)
        .and_then(|v| v.as_table())
        .unwrap_or_else(|| panic!("no [{name}] in the fixture"));
    let get = |key: &str| -> f64 {
        let v = t
            .get(key)
            .unwrap_or_else(|| panic!("[{name}] has no {key}"));
        number(v.as_str().unwrap())
    };
    // the model string: "floor = roll, contact = roll, m1 = 1, ..."; defaults m = r = g = 1, k = 1/2
    let model = t["model"].as_str().unwrap();
    let param = |key: &str, default: f64| -> f64 {
        model
            .split(", ")
            .filter_map(|kv| kv.split_once(" = "))
            .find(|(k, _)| *k == key)
            .map_or(default, |(_, v)| number(v))
    };
    let p = Params {
        m1: param("m1", 1.0),
        m2: param("m2", 1.0),
        r1: param("r1", 1.0),
        r2: param("r2", 1.0),
        k1: param("k1", 0.5),
        k2: param("k2", 0.5),
        g: param("g", 1.0),
    };
    let start = RigidState {
        theta: get("pre_theta"),
        theta_dot: get("pre_theta_dot"),
        x1: get("pre_x1"),
        x1_dot: get("pre_x1_dot"),
        phi1: get("pre_phi1"),
        phi1_dot: get("pre_phi1_dot"),
        psi2: get("pre_psi2"),
        psi2_dot: get("pre_psi2_dot"),
        n12: get("pre_N12"),
        f21: get("pre_F21"),
        n1: get("pre_N1"),
        f1: get("pre_F1"),
    };
    Case {
        p,
        start,
        t_pre: get("pre_t"),
        theta_star: get("theta_star"),
        theta_dot_star: get("theta_dot_star"),
        n12_star: get("N12_star"),
        theta_s: get("theta_s"),
        t_s: get("t_s"),
    }
}

/// RK4 step of the compliant model: dt·sqrt(k) = 1.25e-3. RK4's error in the parting angle
/// at a fixed dt·sqrt(k) does not vanish as k grows (observed ≈ 0.06 (dt·sqrt(k))²: 1.5e-4
/// rad at 0.05, 6e-6 at 0.01), so the product is kept this small.
fn compliant_dt(k: f64) -> f64 {
    1.25e-3 / k.sqrt()
}

#[test]
fn compliant_rolling_contacts_stay_closed_through_theta_star_and_part_at_theta_s() {
    let c = case("mujoco_main");
    // tangential springs without a Coulomb limit (rolling); damping critical for m = 1/2
    // observed |theta_part - theta_s|: 2.17e-4, 1.72e-5, 5.1e-7, 1.5e-7 (k^-1.1 to k^-1.5,
    // then the step's resolution)
    let bounds = [(1e3, 5e-4), (1e4, 4e-5), (1e5, 1.5e-6), (1e6, 1e-6)];
    let mut errors = Vec::new();
    for (k, bound) in bounds {
        let m = Compliant::new(k, f64::INFINITY, 0.5);
        let watch = c.theta_star + 0.02;
        let r = run_compliant(
            &c.p,
            &m,
            &c.start,
            c.t_pre,
            compliant_dt(k),
            c.t_s + 1.0,
            watch,
        );
        // closed through theta*: loaded at least half the rigid N12(theta*) (observed 0.0904
        // up to theta* + 0.02, rigid 0.1180 at theta*), first opening far beyond theta*
        assert!(
            r.min_n12_to_watch > 0.5 * c.n12_star,
            "k = {k:e}: N12 fell to {} before theta* + 0.02",
            r.min_n12_to_watch
        );
        let open = r.first_open_theta.expect("the cylinders never part");
        assert!(
            open > c.theta_star + 0.08,
            "k = {k:e}: opened at {open}, theta* = {}",
            c.theta_star
        );
        let err = (r.part_theta - c.theta_s).abs();
        assert!(
            err < bound,
            "k = {k:e}: parts at {} (t = {}), theta_s = {}: error {err:e} > {bound:e}",
            r.part_theta,
            r.part_t,
            c.theta_s
        );
        errors.push(err);
    }
    // the error falls at least 5x and 10x over the first two decades of k (observed 12.6x, 34x)
    assert!(errors[1] < errors[0] / 5.0, "{errors:?}");
    assert!(errors[2] < errors[1] / 10.0, "{errors:?}");
}

#[test]
fn compliant_spring_slider_parts_where_the_rigid_coulomb_branch_ends() {
    // With a Coulomb limit mu = 1e3 (a common stand-in for rolling) the closed rigid branch
    // ends before theta_s: at the cone |F21| = 1e3 N12, where no closed mode is consistent and
    // the contact opens with N12 > 0 (fixture case extra_main_mu_1000). The spring-slider
    // converges there, slowly.
    let c = case("mujoco_main");
    let theta_cone = case("extra_main_mu_1000").theta_s;
    assert!(c.theta_s - theta_cone > 1e-4 && c.theta_s - theta_cone < 2e-4);
    // observed distance to theta_cone: 1.34e-4, 7.0e-5, 3.28e-5, 1.42e-5 (about k^-0.33)
    let bounds = [(1e4, 2e-4), (1e5, 1e-4), (1e6, 5e-5), (1e7, 2.2e-5)];
    let mut dist = Vec::new();
    for (k, bound) in bounds {
        let m = Compliant::new(k, 1e3, 0.5);
        let r = run_compliant(
            &c.p,
            &m,
            &c.start,
            c.t_pre,
            compliant_dt(k),
            c.t_s + 1.0,
            c.theta_star,
        );
        assert!(r.first_open_theta.unwrap() > c.theta_star + 0.08);
        let d = r.part_theta - theta_cone;
        assert!(
            d > 0.0 && d < bound,
            "k = {k:e}: parts at {}, cone at {theta_cone}",
            r.part_theta
        );
        dist.push(d);
    }
    for w in dist.windows(2) {
        assert!(w[1] < w[0] / 1.6, "{dist:?}");
    }
    // at the stiffest k the parting is nearer the cone than theta_s
    assert!(dist[3] < c.theta_s - theta_cone - dist[3]);
}

/// The steps of the time-stepper sequences.
const STEPS: [f64; 6] = [4e-3, 2e-3, 1e-3, 5e-4, 2.5e-4, 1.25e-4];

fn cold(mu_floor: f64, mu_contact: f64) -> Solver {
    Solver {
        mu_floor,
        mu_contact,
        warm: 0.0,
        max_sweeps: 100_000,
    }
}

/// The stepper from zero impulses parts at the first step where parting is admissible, and
/// that angle (interpolated between steps) converges to theta* like O(h).
fn lcp_parts_at_theta_star(name: &str, mu_floor: f64, slope_bound: f64) -> Vec<f64> {
    let c = case(name);
    let mut errors = Vec::new();
    for h in STEPS {
        let r = run_stepper(
            &c.p,
            &c.start,
            c.t_pre,
            h,
            c.t_s + 1.0,
            &cold(mu_floor, 1e3),
        );
        let open = r.first_open_theta.expect("never parts");
        assert_eq!(
            Some(open),
            r.admissible_step_theta,
            "{name}, h = {h:e}: not at the admissible step"
        );
        // the step where it parts is within one step's angle (plus the O(h) bias) of theta*
        assert!(
            (r.part_theta - c.theta_star).abs() < (c.theta_dot_star + slope_bound) * h,
            "{name}, h = {h:e}: parts at {}, theta* = {}",
            r.part_theta,
            c.theta_star
        );
        let err = r.admissible_theta.unwrap() - c.theta_star;
        assert!(
            err.abs() < slope_bound * h,
            "{name}, h = {h:e}: admissible from {err:e} off theta*"
        );
        errors.push(err);
    }
    println!("{name}: admissible angle - theta* for h = {STEPS:?}: {errors:?}");
    // first order: halving h halves the error
    for w in errors.windows(2) {
        let ratio = w[0] / w[1];
        assert!((1.8..2.2).contains(&ratio), "{name}: errors {errors:?}");
    }
    errors
}

#[test]
fn velocity_level_lcp_parts_at_theta_star() {
    // rolling floor and contact (mu = 1e3); observed error of the admissible angle
    // -0.0912 h (-3.63e-4 at h = 4e-3 ... -1.14e-5 at 1.25e-4)
    lcp_parts_at_theta_star("mujoco_main", 1e3, 0.12);
}

#[test]
fn velocity_level_lcp_parts_at_theta_star_on_a_frictionless_floor() {
    lcp_parts_at_theta_star("slip_roll", 0.0, 0.12);
}

#[test]
fn warm_started_lcp_follows_the_closed_branch() {
    let c = case("mujoco_main");
    // fully converged from the previous impulses: parts near theta_s
    // (observed -2.5e-3 at h = 4e-3, then -4e-4 ... -1.8e-4)
    let full = Solver {
        warm: 1.0,
        ..cold(1e3, 1e3)
    };
    // Bullet's defaults: 10 sweeps from 0.85 of the previous impulses (observed 1.0411-1.0413)
    let bullet = Solver {
        warm: 0.85,
        max_sweeps: 10,
        ..cold(1e3, 1e3)
    };
    for h in STEPS {
        let r = run_stepper(&c.p, &c.start, c.t_pre, h, c.t_s + 1.0, &full);
        assert!(
            (r.part_theta - c.theta_s).abs() < 3e-3,
            "h = {h:e}: warm start parts at {}, theta_s = {}",
            r.part_theta,
            c.theta_s
        );
        // parting was admissible all the while
        assert!(r.admissible_theta.unwrap() < c.theta_star + 0.12 * h);
        let r = run_stepper(&c.p, &c.start, c.t_pre, h, c.t_s + 1.0, &bullet);
        assert!(
            r.part_theta > c.theta_star + 0.07,
            "h = {h:e}: Bullet-like solver parts at {}",
            r.part_theta
        );
    }
}
