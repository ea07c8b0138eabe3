//! A mode of the two-cylinder motion by Chebyshev spectral integration in
//! the angle: the fast route of the motion with friction (Gragg–Bulirsch–
//! Stoer and Gauss–Legendre collocation, [`super::solve`], are the
//! independent checks).
//!
//! Why it works: in every mode the accelerations are linear in θ̇², with
//! coefficients that depend on θ alone — q̈ = a(θ) + b(θ) θ̇², λ = α(θ) +
//! β(θ) θ̇². The velocity enters the equations of motion only through the
//! centripetal term r θ̇² (ṙ = 0 while the contact is closed), x1, φ1, ψ2 are
//! cyclic, and a slipping contact's force ∓μk N is fixed in direction by
//! the mode. Two KKT solves at θ (θ̇ = 0 and θ̇ = 1) give a and b. So u = θ̇²
//! obeys the *linear* equation du/dθ = 2a + 2b u (the issue's "θ̇² obeys a
//! linear first-order ODE in θ", in general), solved by quadrature:
//!
//!   u = e^G (u_a + ∫ 2a e^(−G) dθ),  G = ∫ 2b dθ,
//!
//! and every other quantity is a quadrature too: dt = dθ/θ̇, dq̇_i = q̈_i dt,
//! dq_i = q̇_i dt, dW = P dt (P the sliding power). All of them are
//! Chebyshev interpolants on pieces of the angle (the same machinery as the
//! ideal models' t(θ), [`crate::numeric::cheb`]); their values at the
//! points come from one inverse cosine transform each.
//!
//! Parameter: θ = θ_a + σ s^m, σ = the direction of motion. A piece that
//! starts with θ̇ ≠ 0 takes m = 1; a start from rest takes m = 2, where
//! u = s² w with w smooth and positive (u vanishes linearly in θ − θ_a), so
//! dt/ds = m/√w is smooth on both. The m = 2 quadrature for u is carried
//! out with 48 more bits, since w = u/s² divides by s² near s = 0.
//!
//! Pieces: N = bits/2 points (Bernstein ρ ≥ 4 is aimed at); a piece whose
//! interpolants' last coefficients are not below the tolerance is halved,
//! an accepted one sets the next piece 1.5 times longer. Events are sign
//! changes of the watched functions over the points, located by Newton's
//! method on their interpolant and corrected once by the exact value (a KKT
//! solve) at the root. Outputs at given times invert t(s) by Newton's
//! method.
//!
//! The route declines (returns `None`, and the caller integrates the mode
//! by extrapolation instead) where its premise fails: θ̇ reaching 0 inside a
//! piece (the motion would turn back), a start from rest with θ̈ = 0, a stack
//! of more than two cylinders, or pieces that will not converge.

mod dependents;
mod events;
mod piece;
mod time;

use super::gbs::Stats;
use super::solve::{watch_value, watch_values, Event, Hit, Run, Sample, Start};
use crate::error::Result;
use crate::mechanics::system::{self as sy, System};
use crate::numeric::cheb::fixed_sums::LazySums;
use crate::numeric::cheb::{smooth_at_least, Roots};
use dependents::{dependents, moving};
use events::{coeffs64, first_bracket, reads_positions};
use piece::{attempt, Attempt, Setup, REST_GUARD};
use rug::Float;

/// The settings of a run: the tolerance, what the outputs carry, and the
/// natural scales of the motion for mixed absolute/relative error tests.
#[derive(Debug, Clone)]
pub struct Settings {
    /// Tolerance of every interpolant (relative to its size plus its scale).
    pub tol: Float,
    /// Whether the outputs carry every column (else t and θ only).
    pub full: bool,
    /// Time sqrt(r/g).
    pub ts: Float,
    /// Length r = r1 + r2.
    pub r: Float,
    /// Energy m2 g r.
    pub escale: Float,
}

/// Most pieces per mode before the route declines (and four times as many
/// attempts, shortened ones included).
const MAX_PIECES: usize = 400;

/// The next piece's length over this one's, from how many of its N
/// coefficients the interpolants needed (k): with ρ^−k = tol and ρ roughly
/// ∝ 1/L, L'/L = exp(ln(1/tol)(1/k − 1/k')) puts the next piece at k' =
/// 0.65 N; between 0.7 and 2.5.
fn growth(k: usize, n: usize, tol: &Float) -> f64 {
    let b = -tol.clone().ln().to_f64();
    let k = k.max(1) as f64;
    let target = 0.65 * n as f64;
    (b * (1.0 / k - 1.0 / target)).exp().clamp(0.7, 2.5)
}

/// The first piece of a moving start: Δθ = `cap`, or 1.5 times the
/// distance u/(2|θ̈|) to where θ̇ would vanish behind the start (a branch
/// point of 1/θ̇; ρ ≈ 4.4) if that is less.
fn behind(s: &Sample, cap: f64) -> Float {
    let p = s.t.prec();
    let ith = sy::th(0);
    let acc = Float::with_val(p, s.qdd[ith].abs_ref());
    let cap = Float::with_val(p, cap);
    if acc.is_zero() {
        // θ̇ does not slow down: nothing behind the start
        return cap;
    }
    let d = Float::with_val(p, s.v[ith].square_ref()) / (acc * 2u32);
    cap.min(&(d * 1.5f64))
}

/// A mode from `start` by spectral integration in the angle: outputs at
/// `times` (ascending, ≥ start.t), stopping at the first terminal event or
/// at `t_end`. Without `full` the outputs carry t and θ only. `None`: the
/// route declines (see the module notes).
///
/// Errors: a singular KKT system.
pub fn run(
    sys: &mut System,
    start: &Start,
    times: &[Float],
    t_end: &Float,
    events: &[Event],
    set: &Settings,
) -> Result<Option<Run>> {
    let (tol, full, sc) = (&set.tol, set.full, set);
    // two cylinders, terminal events only (the friction modes' watches)
    if sys.n != 2 || events.iter().any(|e| !e.terminal) {
        return Ok(None);
    }
    let p = sys.prec;
    let ith = sy::th(0);
    let bits = (-tol.get_exp().unwrap_or(-(p as i32))).max(16) as usize + 8;
    let roots = Roots::new(smooth_at_least((bits / 2).max(12)), p);
    let inv_roots = Roots::new(smooth_at_least(roots.n() * 2 / 3), p);
    let cos64: Vec<f64> = (0..4 * roots.n())
        .map(|m| (m as f64 * std::f64::consts::PI / (2 * roots.n()) as f64).cos())
        .collect();
    let deps = dependents(sys, start.q);
    let rest_roots = start.v[sy::th(0)]
        .is_zero()
        .then(|| Roots::new(roots.n(), p + REST_GUARD));
    let su = Setup {
        roots: &roots,
        rest_roots: rest_roots.as_ref(),
        tol,
        sc,
        moving: moving(sys, &deps),
        deps,
        node_positions: events.iter().any(|e| reads_positions(&e.watch)),
    };
    let mut evals = 0u64;
    let mut t0 = Float::with_val(p, &start.t);
    let mut q0 = start.q.to_vec();
    let mut v0 = start.v.to_vec();
    let mut work0 = Float::with_val(p, &start.work);
    let first = sys.accel(&q0, &v0)?;
    evals += 1;
    let (mut m, dir) = if v0[ith].is_zero() {
        let a = &first.qdd[ith];
        if a.is_zero() {
            return Ok(None);
        }
        (2u32, if a.is_sign_negative() { -1 } else { 1 })
    } else {
        (1u32, if v0[ith].is_sign_negative() { -1 } else { 1 })
    };
    // the first piece: Δθ = 1/4 from rest; else Δθ = 0.4, or twice the
    // distance to where θ̇ would vanish behind the start (a branch point of
    // 1/θ̇) if that is less
    let cap = 0.4f64;
    let mut len = if m == 2 {
        // from rest u ≈ 2a Δ + a′ Δ² (Δ = θ − θa, a = θ̈ at rest): its
        // other zero Δ* = −2a/a′ puts branch points of 1/√w at s = ±i√|Δ*|
        // (near the top a ∝ θ: s* = √(2 θ0)); a piece of length s* keeps
        // ρ ≈ 4.6
        let h = Float::with_val(p, 1u32) >> (p as i32 / 3);
        let mut qh = q0.clone();
        qh[ith] += Float::with_val(p, &h * dir);
        let zero = vec![Float::new(p); v0.len()];
        let ah = sys.accel(&qh, &zero)?;
        evals += 1;
        let da = Float::with_val(p, &ah.qdd[ith] - &first.qdd[ith]) / &h * dir;
        let star = (Float::with_val(p, &first.qdd[ith] / &da).abs() * 2u32).sqrt();
        if star.is_finite() {
            Float::with_val(p, 0.5f64).min(&(star * 1.25f64))
        } else {
            Float::with_val(p, 0.5f64)
        }
    } else {
        let smp = Sample {
            t: t0.clone(),
            q: q0.clone(),
            v: v0.clone(),
            qdd: first.qdd.clone(),
            lambda: Vec::new(),
            work: work0.clone(),
            power: Float::new(p),
            trig: Vec::new(),
            energy: None,
        };
        behind(&smp, cap)
    };
    let tiny = Float::with_val(p, 1u32) >> (p as i32 / 2);
    let mut outputs = Vec::new();
    let mut next = 0usize;
    let mut start_val: Vec<Option<Float>> = {
        let smp0 = Sample {
            t: t0.clone(),
            q: q0.clone(),
            v: v0.clone(),
            qdd: first.qdd.clone(),
            lambda: first.lambda.clone(),
            work: work0.clone(),
            power: Float::new(p),
            trig: Vec::new(),
            energy: None,
        };
        events
            .iter()
            .enumerate()
            .map(|(k, e)| {
                let g = watch_value(&e.watch, &smp0);
                let zero = match start.snap.get(k) {
                    Some(s) => Float::with_val(p, g.abs_ref()) <= *s,
                    None => g.is_zero(),
                };
                (!zero).then_some(g)
            })
            .collect()
    };
    let mut pieces = 0u64;
    let mut checkpoints = Vec::new();
    let mut shortened = false;
    for _ in 0..4 * MAX_PIECES {
        crate::cancel::check()?;
        if pieces as usize >= MAX_PIECES {
            break;
        }
        let at = attempt(sys, &su, m, dir, &len, &t0, &q0, &v0, &work0, &mut evals)?;
        let pc = match at {
            Attempt::Done(pc) => pc,
            Attempt::Shorter => {
                len *= 0.6f64;
                shortened = true;
                if len < tiny {
                    return Ok(None);
                }
                continue;
            }
            Attempt::Decline => return Ok(None),
        };
        pieces += 1;
        // the first sign change of each watched function over the piece
        let end_smp = pc.sample(sys, &pc.len)?;
        // per node, every watch at once (one sin/cos for all that need it)
        let per_node: Vec<Vec<Float>> = pc
            .nodes
            .iter()
            .map(|(_, s)| watch_values(events.iter().map(|e| &e.watch), s))
            .collect();
        let node_vals: Vec<Vec<Float>> = (0..events.len())
            .map(|k| per_node.iter().map(|v| v[k].clone()).collect())
            .collect();
        let end_vals: Vec<Float> = watch_values(events.iter().map(|e| &e.watch), &end_smp);
        crate::cancel::check()?;
        let brackets: Vec<Option<(Float, Float)>> = (0..events.len())
            .map(|k| {
                if events[k].terminal && !crate::cancel::cancelled() {
                    let c64 = coeffs64(&node_vals[k], &cos64);
                    let at: Vec<&Float> = pc.nodes.iter().map(|(s, _)| s).collect();
                    first_bracket(
                        &at,
                        &pc.len,
                        start_val[k].as_ref(),
                        &node_vals[k],
                        &end_vals[k],
                        &c64,
                    )
                } else {
                    None
                }
            })
            .collect();
        crate::cancel::check()?;
        let earliest = brackets
            .iter()
            .flatten()
            .map(|(_, hi)| hi)
            .min_by(|a, b| a.total_cmp(b))
            .cloned();
        // an event: the earliest root among the brackets that start before
        // the earliest bracket ends
        let mut hit: Option<(usize, Float, Sample, Float)> = None;
        if let Some(e) = earliest {
            for (k, br) in brackets.iter().enumerate() {
                let Some((lo, hi)) = br else { continue };
                if *lo > e {
                    continue;
                }
                let (s, smp, t_err) = pc.root(sys, &su, &events[k], &node_vals[k], lo, hi)?;
                if hit.as_ref().is_none_or(|h| s < h.1) {
                    hit = Some((k, s, smp, t_err));
                }
            }
        }
        for (k, g) in end_vals.into_iter().enumerate() {
            if !g.is_zero() {
                start_val[k] = Some(g);
            }
        }
        let t_stop = match &hit {
            Some((_, _, smp, _)) => smp.t.clone(),
            None => pc.t_end(),
        };
        let t_lim = t_stop.clone().min(t_end);
        // outputs inside the piece; many of them: s(t) interpolated first
        // (an output at the event's own time is after the event, as for the
        // time integrators)
        let count = times[next..]
            .iter()
            .take_while(|x| **x <= t_lim && (hit.is_none() || **x < t_stop))
            .count();
        let inverse = if count >= roots.n() / 2 {
            // s(t) needs fewer points than the piece's hardest function:
            // two thirds of them first
            pc.inverse(&inv_roots, &t_lim, tol)
                .or_else(|| pc.inverse(&roots, &t_lim, tol))
        } else {
            None
        };
        // s(t) summed in fixed point where it applies (an output only read)
        let inverse_fx = LazySums::at(piece::fixed_prec(tol, p));
        let mut s_at = [Float::new(p)];
        for (i, tau) in times[next..next + count].iter().enumerate() {
            if i % 64 == 0 {
                crate::cancel::check()?;
            }
            let tau = Float::with_val(p, tau);
            let s = match &inverse {
                Some(f) => {
                    let s = if inverse_fx.eval(&[f], &f.a, &f.b, &tau, &mut s_at) {
                        std::mem::replace(&mut s_at[0], Float::new(p))
                    } else {
                        f.eval(&tau, p)
                    };
                    s.max(&Float::new(p)).min(&pc.len)
                }
                None => pc.invert_at(&tau),
            };
            let mut smp = if full {
                pc.row_sample(sys, &s, &tau)?
            } else {
                pc.theta_sample(&s)
            };
            smp.t = tau;
            outputs.push(smp);
        }
        next += count;
        let stats = Stats {
            steps: pieces,
            rejected: 0,
            evals,
            max_column: roots.n(),
        };
        if let Some((k, _, smp, t_err)) = hit {
            if smp.t <= *t_end {
                return Ok(Some(Run {
                    outputs,
                    hits: vec![Hit {
                        event: k,
                        at: smp.clone(),
                        t_err,
                    }],
                    stopped: true,
                    last: smp,
                    max_drift: Float::new(p),
                    projections: 0,
                    stats,
                    checkpoints,
                }));
            }
        }
        if t_stop >= *t_end {
            let tau = Float::with_val(p, t_end);
            let lo = (Float::new(p), pc.t0.clone());
            let hi = (pc.len.clone(), pc.t_end());
            let s = pc.invert(&tau, &lo, &hi);
            let mut last = pc.sample(sys, &s)?;
            last.t = tau;
            return Ok(Some(Run {
                outputs,
                hits: Vec::new(),
                stopped: false,
                last,
                max_drift: Float::new(p),
                projections: 0,
                stats,
                checkpoints,
            }));
        }
        // the next piece from the end of this one
        checkpoints.push(end_smp.clone());
        t0 = end_smp.t.clone();
        q0 = end_smp.q.clone();
        v0 = end_smp.v.clone();
        work0 = end_smp.work.clone();
        let g = growth(pc.used, roots.n(), tol);
        if m == 2 {
            // from s to θ: the piece spanned Δθ = L²
            len.square_mut();
        }
        len *= g;
        m = 1;
        // graded towards a branch point behind: at least 1.5 times its
        // distance (ρ ≈ 4.4), unless this piece had to be shortened
        if !shortened {
            len = len.max(&behind(&end_smp, cap));
        }
        shortened = false;
    }
    Ok(None)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::Exact;
    use crate::integrate::solve::Watch;
    use crate::integrate::solve::{self, Opts};
    use crate::mechanics::system::{Row, SlipTerm, StackModel, Tangent};
    use crate::model::{Contact, Floor, Ideal};
    use crate::numeric::cheb::ChebFit;

    const P: u32 = 200;

    fn f(x: f64) -> Float {
        Float::with_val(P, x)
    }

    /// The two cylinders of the paper in a mode: `slips` lists the sliding
    /// contacts with the sign of their slip (μk = 3/10).
    fn system(floor: Floor, contact: Contact, slips: &[(Tangent, i32)]) -> System {
        let model = Ideal::paper_default(Exact::parse("theta0", "1/10", false).unwrap());
        let mut sm = StackModel::from_model(&model);
        sm.floor = floor;
        sm.contacts[0] = contact;
        let mut sys = System::new(&sm, P).unwrap();
        for &(at, sign) in slips {
            let row = match at {
                Tangent::Floor => Row::FloorNormal,
                Tangent::Line(j) => Row::Normal(j),
            };
            let normal = sys.rows.iter().position(|r| *r == row).unwrap();
            sys.slips.push(SlipTerm {
                at,
                normal,
                mu_sigma: Float::with_val(P, rug::Rational::from((3 * sign, 10))),
            });
        }
        sys
    }

    fn modes() -> Vec<System> {
        vec![
            system(Floor::Roll, Contact::Roll, &[]),
            system(Floor::Roll, Contact::Slip, &[(Tangent::Line(0), 1)]),
            system(Floor::Slip, Contact::Roll, &[(Tangent::Floor, -1)]),
            system(
                Floor::Slip,
                Contact::Slip,
                &[(Tangent::Floor, 1), (Tangent::Line(0), -1)],
            ),
            system(Floor::Fixed, Contact::Slip, &[(Tangent::Line(0), -1)]),
        ]
    }

    /// x1, y1, φ1, ψ2, θ, r of the paper's cylinders (y1 = r1, r = r1 + r2).
    fn coords(theta: f64) -> Vec<Float> {
        vec![f(0.25), f(1.0), f(-0.5), f(0.75), f(theta), f(2.0)]
    }

    /// The route's premise: with ṙ = 0 the KKT solution is a + b θ̇², in
    /// every mode, whatever the other rates (x1, φ1, ψ2 are cyclic).
    #[test]
    fn accelerations_are_affine_in_theta_dot_squared() {
        let lim = Float::with_val(P, 1u32) >> (P as i32 - 16);
        for mut sys in modes() {
            for (theta, thd) in [(0.2, 0.3), (0.7, -1.1), (1.3, 2.5)] {
                let q = coords(theta);
                let (a, ab) = sys.accel_pair(&q, 0, 0).unwrap();
                let v = vec![f(0.3), f(0.0), f(-0.7), f(1.1), f(thd), f(0.0)];
                let acc = sys.accel(&q, &v).unwrap();
                let u = Float::with_val(P, f(thd).square_ref());
                let pairs = acc
                    .qdd
                    .iter()
                    .zip(a.qdd.iter().zip(&ab.qdd))
                    .chain(acc.lambda.iter().zip(a.lambda.iter().zip(&ab.lambda)));
                for (x, (a0, a1)) in pairs {
                    let pred = Float::with_val(P, a1 - a0) * &u + a0;
                    let d = Float::with_val(P, x - &pred).abs();
                    assert!(
                        d < lim,
                        "{:?} {:?}: {x} vs {pred}",
                        sys.floor,
                        sys.slips.len()
                    );
                }
            }
        }
    }

    /// A watched function that dips below zero and comes back between two
    /// points is found by the samples of its interpolant between them, in
    /// any units: the same bracket with every value scaled by 2^k, k = −1500
    /// … 1500 (beyond f64's range both ways: unscaled, the samples were 0 or
    /// infinite and the graze was lost).
    #[test]
    fn a_graze_between_two_points_is_bracketed() {
        let n = 16;
        let roots = Roots::new(n, P);
        let len = f(1.0);
        let pts = ChebFit::points(&Float::new(P), &len, &roots, P);
        let asc: Vec<&Float> = pts.iter().rev().collect();
        // g = (s − c)² − δ with c midway between two points and √δ a third of
        // their gap: every point and both ends are positive
        let (lo, hi) = (asc[9].to_f64(), asc[10].to_f64());
        let c = (lo + hi) / 2.0;
        let d = ((hi - lo) / 6.0).powi(2);
        let cos: Vec<f64> = (0..4 * n)
            .map(|m| (m as f64 * std::f64::consts::PI / (2 * n) as f64).cos())
            .collect();
        let mut first = None;
        for k in [0, -1500, -400, 400, 1500] {
            let g = |x: &Float| -> Float { Float::with_val(P, (x.to_f64() - c).powi(2) - d) << k };
            let vals: Vec<Float> = asc.iter().map(|x| g(x)).collect();
            assert!(vals.iter().all(|v| v.is_sign_positive()));
            let c64 = coeffs64(&vals, &cos);
            let end = g(&len);
            let start = g(&Float::new(P));
            let (a, b) = first_bracket(&asc, &len, Some(&start), &vals, &end, &c64)
                .unwrap_or_else(|| panic!("the graze is seen at 2^{k}"));
            let root = c - d.sqrt();
            assert!(a.to_f64() <= root && root <= b.to_f64(), "{a} {b} {root}");
            assert!(a.to_f64() >= lo && b.to_f64() <= hi);
            // the same bracket in every unit
            let first = first.get_or_insert((a.clone(), b.clone()));
            assert_eq!((&first.0, &first.1), (&a, &b), "2^{k}");
            // without the samples between points there is no sign change
            assert!(first_bracket(&asc, &len, Some(&start), &vals, &end, &[0.0]).is_none());
        }
    }

    /// A start at t = 0 with nothing dissipated and no snapping.
    fn at_zero<'a>(q: &'a [Float], v: &'a [Float]) -> Start<'a> {
        Start {
            t: Float::new(P),
            q,
            v,
            work: Float::new(P),
            snap: Vec::new(),
        }
    }

    fn settings(tol_bits: i32) -> Settings {
        Settings {
            tol: Float::with_val(P, 1u32) >> tol_bits,
            full: true,
            ts: f(2f64.sqrt()),
            r: f(2.0),
            escale: f(2.0),
        }
    }

    /// A motion that turns back (θ̇ toward the top, too slow to pass it):
    /// the route declines instead of integrating through θ̇ = 0.
    #[test]
    fn a_motion_that_turns_back_is_declined() {
        let mut sys = system(Floor::Roll, Contact::Slip, &[(Tangent::Line(0), -1)]);
        let q = coords(0.3);
        let mut v = vec![Float::new(P); 6];
        v[sy::th(0)] = f(-0.05);
        let start = at_zero(&q, &v);
        let r = run(&mut sys, &start, &[], &f(20.0), &[], &settings(150)).unwrap();
        assert!(r.is_none(), "a turning motion must be declined");
    }

    /// One sliding mode (floor rolling, contact sliding) from a moving start
    /// to N12 = 0, by this route and by GBS extrapolation: the event time,
    /// the state there and outputs on the way agree to the tolerance.
    #[test]
    fn agrees_with_extrapolation_on_a_sliding_mode() {
        let tol_bits = 150;
        let mut a = system(Floor::Roll, Contact::Slip, &[(Tangent::Line(0), 1)]);
        let mut b = a.clone();
        let q = coords(0.4);
        let mut v = vec![Float::new(P); 6];
        // rolling floor: ẋ1 = r1 φ̇1; the contact slides forwards
        v[sy::X1] = f(-0.05);
        v[sy::PHI1] = f(-0.05);
        v[sy::th(0)] = f(0.3);
        v[sy::psi(0)] = f(-0.2);
        let start = at_zero(&q, &v);
        let n12 = a.rows.iter().position(|r| *r == Row::Normal(0)).unwrap();
        let events = vec![Event {
            name: "separation".into(),
            watch: Watch::Multiplier(n12),
            terminal: true,
        }];
        let times = vec![f(0.5), f(1.25)];
        let set = settings(tol_bits);
        let s = run(&mut a, &start, &times, &f(50.0), &events, &set)
            .unwrap()
            .expect("the route takes this mode");
        let mut opts = Opts::for_prec(P - 40, 8, &set.ts);
        opts.hcap = Some(f(1.0));
        let g = solve::run_from(&mut b, &start, &times, &f(50.0), &events, &opts).unwrap();
        assert!(s.stopped && g.stopped);
        let lim = Float::with_val(P, 1u32) >> (tol_bits - 12);
        let close = |x: &Float, y: &Float, what: &str| {
            let d = Float::with_val(P, x - y).abs();
            assert!(d < lim, "{what}: {x} vs {y}");
        };
        close(&s.last.t, &g.last.t, "t_s");
        for (x, y) in s.last.q.iter().zip(&g.last.q) {
            close(x, y, "q at separation");
        }
        for (x, y) in s.last.v.iter().zip(&g.last.v) {
            close(x, y, "q̇ at separation");
        }
        close(&s.last.work, &g.last.work, "work");
        assert_eq!(s.outputs.len(), 2);
        for (x, y) in s.outputs.iter().zip(&g.outputs) {
            for (c, d) in x.q.iter().zip(&y.q).chain(x.v.iter().zip(&y.v)) {
                close(c, d, "output state");
            }
            for (c, d) in x.lambda.iter().zip(&y.lambda) {
                close(c, d, "output forces");
            }
        }
    }
}
