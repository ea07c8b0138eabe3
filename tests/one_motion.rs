//! The ideal models through the hybrid engine without their fast path: the
//! energy route (closed-form θ̇²(θ), quadrature in θ, polynomial roots of
//! the events) against the spectral route in θ that every dissipative phase
//! takes (`Method::Spectral`: the equations of motion integrated, events
//! found as roots of interpolants), on the same ideal case at the same
//! working precision. Every column at times in the closed phase and in
//! flight, every event (kind, time, angle) and the first impact agree to
//! the precision's digits less a margin: two independent routes through one
//! motion.

use cylroll::exact::Exact;
use cylroll::model::input::model_from_pairs;
use cylroll::model::Model;
use cylroll::motion::{self, Caches, Method, Request};
use rug::Float;
use std::collections::BTreeMap;

fn model(text: &str) -> Model {
    let pairs: BTreeMap<String, String> = text
        .split(", ")
        .filter_map(|kv| kv.split_once(" = "))
        .map(|(k, v)| (k.trim().to_string(), v.trim().to_string()))
        .collect();
    model_from_pairs(&pairs).unwrap()
}

fn run(m: &Model, method: Method, times: &[&str], prec: u32) -> motion::Motion {
    let mut req = Request::to_end(
        times
            .iter()
            .map(|t| Exact::parse("t", t, false).unwrap())
            .collect(),
    );
    req.method = method;
    motion::run(m, &req, prec, &mut Caches::default())
        .unwrap_or_else(|e| panic!("{} {method:?}: {e}", m.describe()))
}

/// |a − b| ≤ 10^−digits · max(1, |a|).
fn close(what: &str, a: &Float, b: &Float, digits: i32) {
    let d = Float::with_val(a.prec(), a - b).abs().to_f64();
    let scale = a.to_f64().abs().max(1.0);
    assert!(
        d <= 10f64.powi(-digits) * scale,
        "{what}: energy route {a} vs spectral {b} (differ by {d:e})"
    );
}

#[test]
fn the_energy_route_and_the_spectral_route_give_one_motion_for_every_ideal_law() {
    const PREC: u32 = 200; // about 60 decimal digits of arithmetic
    const DIGITS: i32 = 40;
    for (text, times) in [
        (
            "floor = roll, contact = roll, theta0 = 1/10",
            &["1", "3.5", "5.1", "5.5", "5.9"][..],
        ),
        (
            "floor = slip, contact = roll, theta0 = 1/10",
            &["1", "3", "4.5"][..],
        ),
        (
            "floor = roll, contact = slip, theta0 = 1/10",
            &["1", "3", "4.1"][..],
        ),
        (
            "floor = slip, contact = slip, theta0 = 1/10",
            &["1", "2.8", "3.9"][..],
        ),
        (
            "floor = fixed, contact = roll, theta0 = 1/20",
            &["1", "6", "7"][..],
        ),
        (
            "floor = roll, contact = roll, m1 = 2, m2 = 1/2, r1 = 3/2, r2 = 1/2, k1 = 1/3, k2 = 9/10, theta0 = 1/10",
            &["1", "5", "6.5", "7.2"][..],
        ),
    ] {
        let m = model(text);
        let a = run(&m, Method::Auto, times, PREC);
        let b = run(&m, Method::Spectral, times, PREC);
        assert!(
            a.routes.contains(&motion::Route::Energy),
            "{text}: the fast path was not taken ({:?})",
            a.routes
        );
        assert!(
            !b.routes.contains(&motion::Route::Energy),
            "{text}: Method::Spectral took the energy route"
        );
        assert_eq!(a.events.len(), b.events.len(), "{text}: event counts");
        for (ea, eb) in a.events.iter().zip(&b.events) {
            assert_eq!(ea.kind, eb.kind, "{text}");
            assert_eq!(ea.which, eb.which, "{text}");
            close(&format!("{text} {:?} t", ea.kind), &ea.at.t, &eb.at.t, DIGITS);
            close(
                &format!("{text} {:?} theta", ea.kind),
                &ea.at.theta,
                &eb.at.theta,
                DIGITS,
            );
        }
        let (ia, ib) = (a.impact.as_ref().unwrap(), b.impact.as_ref().unwrap());
        assert_eq!(ia.surface, ib.surface, "{text}");
        for (w, x, y) in [
            ("t_impact", &ia.t, &ib.t),
            ("x1_impact", &ia.x1, &ib.x1),
            ("x2_impact", &ia.x2, &ib.x2),
            ("y2_impact", &ia.y2, &ib.y2),
        ] {
            close(&format!("{text} {w}"), x, y, DIGITS);
        }
        assert_eq!(a.rows.len(), times.len());
        assert_eq!(b.rows.len(), times.len());
        for (i, (ra, rb)) in a.rows.iter().zip(&b.rows).enumerate() {
            let (ca, cb) = (ra.columns(), rb.columns());
            assert_eq!(ca.len(), cb.len());
            for (k, (x, y)) in ca.iter().zip(&cb).enumerate() {
                close(&format!("{text} t = {} column {k}", times[i]), x, y, DIGITS);
            }
        }
    }
}
