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

use super::gbs::Stats;
use super::solve::{watch_value, watch_values, Event, Hit, Run, Sample, Start, Watch};
use crate::error::Result;
use crate::mechanics::system::{self as sy, Accel, Row, System};
use crate::model::Floor;
use crate::numeric::cheb::{smooth_at_least, ChebFit, Roots};
use rug::{Assign, Float};

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

/// Extra bits of the m = 2 quadrature for u.
const REST_GUARD: u32 = 48;

/// One piece: the state at s = 0 and the interpolants on [0, L].
struct Piece {
    m: u32,
    dir: i32,
    len: Float,
    t0: Float,
    q0: Vec<Float>,
    v0: Vec<Float>,
    work0: Float,
    /// t(s) − t0.
    dt: ChebFit,
    /// dt/ds = m/√w (u = θ̇² = s^(2(m−1)) w; θ̇ = σ s^(m−1) m/rate).
    rate: ChebFit,
    /// q̇_i(s) − q̇_i(0) of the coordinates that move besides θ.
    vel: Vec<(usize, ChebFit)>,
    /// q_i(s) − q_i(0).
    pos: Vec<(usize, ChebFit)>,
    /// W(s) − W(0) (None without slipping contacts).
    work: Option<ChebFit>,
    deps: Vec<Dependent>,
    /// t(s) − t0 and dt/ds at 128, 256, … bits up to 3p/4, their
    /// coefficients cut where they fall below the precision (the first
    /// Newton steps of an inversion).
    lower: Vec<(u32, ChebFit, ChebFit)>,
    /// t(s) − t0 and dt/ds in f64 (Newton seeds).
    dt64: Vec<f64>,
    rate64: Vec<f64>,
    /// The samples at the points, in ascending s, with their s.
    nodes: Vec<(Float, Sample)>,
    /// The most coefficients any interpolant needed (above its tolerance).
    used: usize,
    /// Bases of the inversions' Newton steps (lower precisions, full).
    scratch: std::cell::RefCell<(Vec<Float>, Vec<Float>)>,
}

enum Attempt {
    Done(Box<Piece>),
    /// The interpolants did not converge: a shorter piece.
    Shorter,
    /// θ̇ vanishes inside (or w is not positive): the route declines.
    Decline,
}

/// A coordinate fixed by a velocity constraint of the mode: q̇_dep =
/// Σ c_i q̇_i, so q_dep − q_dep(0) = Σ c_i (q_i − q_i(0)) (constant
/// coefficients: r is held while the contact is closed). No terms: held.
type Dependent = (usize, Vec<(usize, Float)>);

/// The dependents of a two-cylinder mode, in an order in which each needs
/// only coordinates before it: φ1 held (a fixed floor), x1 rolling with φ1
/// (x1 = r1 φ1 + const) or held, ψ2 rolling on cylinder 1
/// (ψ̇2 = (r1 φ̇1 − r θ̇)/r2).
fn dependents(sys: &System, q0: &[Float]) -> Vec<Dependent> {
    let p = sys.prec;
    let mut out = Vec::new();
    if sys.rows.contains(&Row::Hold) {
        out.push((sy::PHI1, Vec::new()));
    }
    if sys.rows.contains(&Row::FloorFriction) {
        out.push(match sys.floor {
            Floor::Roll => (sy::X1, vec![(sy::PHI1, sys.rho[0].clone())]),
            _ => (sy::X1, Vec::new()),
        });
    }
    if sys.rows.contains(&Row::Friction(0)) {
        let r2 = &sys.rho[1];
        out.push((
            sy::psi(0),
            vec![
                (sy::PHI1, Float::with_val(p, &sys.rho[0] / r2)),
                (sy::th(0), -Float::with_val(p, &q0[sy::rr(0)] / r2)),
            ],
        ));
    }
    out
}

/// The coordinates integrated besides θ: x1, φ1, ψ2 unless a dependent (y1
/// and r are held by the normal constraints while the contact is closed).
fn moving(sys: &System, deps: &[Dependent]) -> Vec<usize> {
    (0..sys.nq())
        .filter(|&i| i != sy::Y1 && i != sy::th(0) && i != sy::rr(0))
        .filter(|i| deps.iter().all(|(d, _)| d != i))
        .collect()
}

/// Fills the dependents of (q, q̇) from the rest (q0: the piece's start).
fn fill_dependents(deps: &[Dependent], q0: &[Float], q: &mut [Float], v: &mut [Float]) {
    for (d, terms) in deps {
        let p = q[*d].prec();
        let mut x = Float::with_val(p, &q0[*d]);
        let mut y = Float::new(p);
        for (i, c) in terms {
            x += Float::with_val(p, &q[*i] - &q0[*i]) * c;
            y += Float::with_val(p, &v[*i] * c);
        }
        q[*d] = x;
        v[*d] = y;
    }
}

/// Whether the fit's last coefficients are below tol·(max |f| + floor);
/// `used` grows to the number of coefficients above that level.
fn within(f: &ChebFit, tol: &Float, floor: &Float, used: &mut usize) -> bool {
    let p = f.prec();
    let lim = Float::with_val(p, &f.fmax + floor) * tol;
    let k =
        f.c.iter()
            .rposition(|c| c.cmp_abs(&lim) == Some(std::cmp::Ordering::Greater));
    *used = (*used).max(k.map_or(0, |k| k + 1));
    f.tail() <= lim
}

/// θ(s) = θ_a + σ s^m.
fn theta_at(th0: &Float, dir: i32, m: u32, s: &Float) -> Float {
    let p = s.prec();
    let sm = if m == 1 {
        s.clone()
    } else {
        Float::with_val(p, s.square_ref())
    };
    Float::with_val(p, th0 + sm * dir)
}

/// a and b of q̈ = a + b θ̇² (and of λ) at angle θ: two KKT solves.
fn probe(sys: &mut System, q: &mut [Float], th: &Float) -> Result<(Accel, Accel)> {
    q[sy::th(0)].assign(th);
    let (a0, mut a1) = sys.accel_pair(q, 0)?;
    for (x, y) in a1.qdd.iter_mut().zip(&a0.qdd) {
        *x -= y;
    }
    for (x, y) in a1.lambda.iter_mut().zip(&a0.lambda) {
        *x -= y;
    }
    Ok((a0, a1))
}

/// x + y·u for vectors.
fn affine(x: &[Float], y: &[Float], u: &Float) -> Vec<Float> {
    x.iter()
        .zip(y)
        .map(|(a, b)| Float::with_val(a.prec(), a + Float::with_val(a.prec(), b * u)))
        .collect()
}

struct Setup<'a> {
    roots: &'a Roots,
    /// The same points with twiddles at p + [`REST_GUARD`] (+ 32) bits, for
    /// a start from rest.
    rest_roots: Option<&'a Roots>,
    tol: &'a Float,
    sc: &'a Settings,
    moving: Vec<usize>,
    deps: Vec<Dependent>,
    /// Whether a watched function reads a moving coordinate: only then do
    /// the samples at the points carry their positions and the work (else
    /// those of s = 0; the samples serve the watched functions and the
    /// times).
    node_positions: bool,
}

/// Whether a watched function reads a coordinate other than θ.
fn reads_positions(w: &Watch) -> bool {
    match w {
        Watch::Coord(i) | Watch::Reach { i, .. } => *i != sy::th(0),
        Watch::Lin(terms) => terms.iter().any(|(w, _)| reads_positions(w)),
        Watch::Height { th, .. } | Watch::FreeNormal { th, .. } => *th != sy::th(0),
        Watch::Multiplier(_) | Watch::Rate(_) => false,
    }
}

#[allow(clippy::too_many_arguments)]
fn attempt(
    sys: &mut System,
    su: &Setup,
    m: u32,
    dir: i32,
    len: &Float,
    t0: &Float,
    q0: &[Float],
    v0: &[Float],
    work0: &Float,
    evals: &mut u64,
) -> Result<Attempt> {
    let p = sys.prec;
    let n = su.roots.n();
    let ith = sy::th(0);
    let zero = Float::new(p);
    let pts = ChebFit::points(&zero, len, su.roots, p);
    let th0 = &q0[ith];
    let mut used = 0usize;
    let mut parts = Vec::with_capacity(n);
    let mut qp = q0.to_vec();
    for s in &pts {
        parts.push(probe(sys, &mut qp, &theta_at(th0, dir, m, s))?);
        *evals += 2;
    }
    // θ'(s) = σ m s^(m−1)
    let dth: Vec<Float> = pts
        .iter()
        .map(|s| {
            let d = if m == 1 {
                Float::with_val(p, 1u32)
            } else {
                Float::with_val(p, s * 2u32)
            };
            d * dir
        })
        .collect();
    let inv_len = Float::with_val(p, len.recip_ref());
    // G = ∫ 2b θ' ds
    let g: Vec<Float> = parts
        .iter()
        .zip(&dth)
        .map(|((_, b), d)| Float::with_val(p, &b.qdd[ith] * d) * 2u32)
        .collect();
    let gfit = ChebFit::from_values(&zero, len, su.roots, p, &g);
    if !within(&gfit, su.tol, &inv_len, &mut used) {
        return Ok(Attempt::Shorter);
    }
    let gv = gfit.antiderivative().values(su.roots, p);
    // u = e^G (u_a + ∫ 2a θ' e^(−G) ds), at hp bits
    let hp = if m == 2 { p + REST_GUARD } else { p };
    let e: Vec<Float> = gv.iter().map(|x| Float::with_val(hp, -x).exp()).collect();
    let j: Vec<Float> = parts
        .iter()
        .zip(&dth)
        .zip(&e)
        .map(|(((a, _), d), e)| Float::with_val(hp, &a.qdd[ith] * d) * e * 2u32)
        .collect();
    let hz = Float::new(hp);
    let hl = Float::with_val(hp, len);
    let hroots = match (m, su.rest_roots) {
        (2, Some(r)) => r,
        _ => su.roots,
    };
    let jfit = ChebFit::from_values(&hz, &hl, hroots, hp, &j);
    let uscale = Float::with_val(p, su.sc.ts.square_ref()).recip() * &inv_len;
    if !within(&jfit, su.tol, &uscale, &mut used) {
        return Ok(Attempt::Shorter);
    }
    let iv = jfit.antiderivative().values(hroots, hp);
    let ua = Float::with_val(hp, v0[ith].square_ref());
    let mut w = Vec::with_capacity(n);
    for ((s, i), e) in pts.iter().zip(&iv).zip(&e) {
        let mut u = Float::with_val(hp, &ua + i) / e;
        if m == 2 {
            u /= Float::with_val(hp, s.square_ref());
        }
        if !u.is_sign_positive() || u.is_zero() {
            return Ok(Attempt::Decline);
        }
        w.push(Float::with_val(p, &u));
    }
    let rate: Vec<Float> = w
        .iter()
        .map(|x| Float::with_val(p, x.sqrt_ref()).recip() * m)
        .collect();
    let rfit = ChebFit::from_values(&zero, len, su.roots, p, &rate);
    let tfloor = Float::with_val(p, &su.sc.ts * &inv_len);
    if !within(&rfit, su.tol, &tfloor, &mut used) {
        return Ok(Attempt::Shorter);
    }
    // θ̇ must not vanish up to the end either
    let r_end = rfit.eval(len, p);
    if !r_end.is_sign_positive() || r_end.is_zero() || !r_end.is_finite() {
        return Ok(Attempt::Decline);
    }
    let dt = rfit.antiderivative();
    let tv = dt.values(su.roots, p);
    // u at the points, and the full velocity
    let u: Vec<Float> = pts
        .iter()
        .zip(&w)
        .map(|(s, w)| {
            if m == 2 {
                Float::with_val(p, s.square_ref()) * w
            } else {
                w.clone()
            }
        })
        .collect();
    let vscale = Float::with_val(p, &su.sc.r / &su.sc.ts);
    let mut vel = Vec::new();
    let mut vnodes: Vec<Vec<Float>> = (0..n)
        .map(|k| {
            let mut v = vec![Float::new(p); sys.nq()];
            let thd = if m == 2 {
                Float::with_val(p, w[k].sqrt_ref()) * &pts[k]
            } else {
                Float::with_val(p, w[k].sqrt_ref())
            };
            v[ith] = thd * dir;
            v
        })
        .collect();
    for &i in &su.moving {
        let f: Vec<Float> = (0..n)
            .map(|k| {
                let (a, b) = &parts[k];
                let acc = Float::with_val(p, &a.qdd[i] + Float::with_val(p, &b.qdd[i] * &u[k]));
                acc * &rate[k]
            })
            .collect();
        let fit = ChebFit::from_values(&zero, len, su.roots, p, &f);
        if !within(
            &fit,
            su.tol,
            &Float::with_val(p, &vscale * &inv_len),
            &mut used,
        ) {
            return Ok(Attempt::Shorter);
        }
        let anti = fit.antiderivative();
        for (k, x) in anti.values(su.roots, p).into_iter().enumerate() {
            vnodes[k][i] = x + &v0[i];
        }
        vel.push((i, anti));
    }
    let mut pos = Vec::new();
    let mut qnodes: Vec<Vec<Float>> = pts
        .iter()
        .map(|s| {
            let mut q = q0.to_vec();
            q[ith] = theta_at(th0, dir, m, s);
            q
        })
        .collect();
    for &i in &su.moving {
        let f: Vec<Float> = (0..n)
            .map(|k| Float::with_val(p, &vnodes[k][i] * &rate[k]))
            .collect();
        let fit = ChebFit::from_values(&zero, len, su.roots, p, &f);
        if !within(
            &fit,
            su.tol,
            &Float::with_val(p, &su.sc.r * &inv_len),
            &mut used,
        ) {
            return Ok(Attempt::Shorter);
        }
        let anti = fit.antiderivative();
        if su.node_positions {
            for (k, x) in anti.values(su.roots, p).into_iter().enumerate() {
                qnodes[k][i] = x + &q0[i];
            }
        }
        pos.push((i, anti));
    }
    for (q, v) in qnodes.iter_mut().zip(&mut vnodes) {
        fill_dependents(&su.deps, q0, q, v);
    }
    let mut lambdas = Vec::with_capacity(n);
    let mut qdds = Vec::with_capacity(n);
    let mut powers = Vec::with_capacity(n);
    for k in 0..n {
        let (a, b) = &parts[k];
        let lam = affine(&a.lambda, &b.lambda, &u[k]);
        let pw = if sys.has_slips() {
            sys.slip_power(&qnodes[k], &vnodes[k], &lam)
        } else {
            Float::new(p)
        };
        qdds.push(affine(&a.qdd, &b.qdd, &u[k]));
        lambdas.push(lam);
        powers.push(pw);
    }
    let (work, wv) = if sys.has_slips() {
        let f: Vec<Float> = powers
            .iter()
            .zip(&rate)
            .map(|(x, r)| Float::with_val(p, x * r))
            .collect();
        let fit = ChebFit::from_values(&zero, len, su.roots, p, &f);
        let floor = Float::with_val(p, &su.sc.escale * &inv_len);
        if !within(&fit, su.tol, &floor, &mut used) {
            return Ok(Attempt::Shorter);
        }
        let anti = fit.antiderivative();
        let wv = if su.node_positions {
            anti.values(su.roots, p)
        } else {
            vec![Float::new(p); n]
        };
        (Some(anti), wv)
    } else {
        (None, vec![Float::new(p); n])
    };
    // the samples at the points, ascending in s
    let mut nodes = Vec::with_capacity(n);
    for k in (0..n).rev() {
        nodes.push((
            pts[k].clone(),
            Sample {
                t: Float::with_val(p, t0 + &tv[k]),
                q: std::mem::take(&mut qnodes[k]),
                v: std::mem::take(&mut vnodes[k]),
                qdd: std::mem::take(&mut qdds[k]),
                lambda: std::mem::take(&mut lambdas[k]),
                work: Float::with_val(p, work0 + &wv[k]),
                power: std::mem::replace(&mut powers[k], Float::new(p)),
            },
        ));
    }
    Ok(Attempt::Done(Box::new(Piece {
        m,
        dir,
        len: len.clone(),
        t0: t0.clone(),
        q0: q0.to_vec(),
        v0: v0.to_vec(),
        work0: work0.clone(),
        dt: dt.clone(),
        rate: rfit.clone(),
        vel,
        pos,
        work,
        deps: su.deps.clone(),
        lower: lower_copies(&dt, &rfit, p),
        used,
        scratch: Default::default(),
        dt64: dt.to_f64(),
        rate64: rfit.to_f64(),
        nodes,
    })))
}

/// `f` rounded to q bits without the trailing coefficients below
/// 2^−(q+8) of the largest.
fn cut(f: &ChebFit, q: u32) -> ChebFit {
    let mut g = f.rounded(q);
    let big =
        g.c.iter()
            .map(|c| c.clone().abs())
            .fold(Float::new(q), |a, b| a.max(&b));
    let small = big >> (q as i32 + 8);
    while g.c.len() > 2 && g.c.last().is_some_and(|c| c.clone().abs() < small) {
        g.c.pop();
    }
    g
}

/// The lower copies of `dt` and `rate` for precision doubling: 128, 256, …
/// bits up to 3/4 p (then one or two full steps end it).
fn lower_copies(dt: &ChebFit, rate: &ChebFit, p: u32) -> Vec<(u32, ChebFit, ChebFit)> {
    let mut out = Vec::new();
    let mut q = 128u32;
    while 4 * q <= 3 * p {
        out.push((q, cut(dt, q), cut(rate, q)));
        q *= 2;
    }
    out
}

impl Piece {
    /// The state (t, q, q̇, W) at s: every interpolant on one basis.
    fn state(&self, s: &Float) -> (Float, Vec<Float>, Vec<Float>, Float) {
        let p = s.prec();
        let ith = sy::th(0);
        let zero = Float::new(p);
        let mut sc = self.scratch.borrow_mut();
        let basis = &mut sc.1;
        ChebFit::basis_into(&zero, &self.len, s, self.dt.c.len(), p, basis);
        let mut q = self.q0.clone();
        let mut v = self.v0.clone();
        q[ith] = theta_at(&self.q0[ith], self.dir, self.m, s);
        let mut thd = Float::with_val(p, self.m) / self.rate.dot(basis);
        if self.m == 2 {
            thd *= s;
        }
        v[ith] = thd * self.dir;
        for (i, f) in &self.vel {
            v[*i] = Float::with_val(p, &self.v0[*i] + f.dot(basis));
        }
        for (i, f) in &self.pos {
            q[*i] = Float::with_val(p, &self.q0[*i] + f.dot(basis));
        }
        fill_dependents(&self.deps, &self.q0, &mut q, &mut v);
        let t = Float::with_val(p, &self.t0 + self.dt.dot(basis));
        let work = match &self.work {
            Some(f) => Float::with_val(p, &self.work0 + f.dot(basis)),
            None => self.work0.clone(),
        };
        (t, q, v, work)
    }

    /// A sample at s with t and θ only (every other value that of s = 0,
    /// no rates, forces or work): for [`run`] without `full` rows.
    fn theta_sample(&self, s: &Float) -> Sample {
        let p = s.prec();
        let mut q = self.q0.clone();
        q[sy::th(0)] = theta_at(&self.q0[sy::th(0)], self.dir, self.m, s);
        let zeros = |n: usize| vec![Float::new(p); n];
        Sample {
            t: Float::new(p),
            q,
            v: zeros(self.v0.len()),
            qdd: zeros(self.v0.len()),
            lambda: Vec::new(),
            work: Float::new(p),
            power: Float::new(p),
        }
    }

    /// The full sample at s (one KKT solve).
    fn sample(&self, sys: &mut System, s: &Float) -> Result<Sample> {
        let (t, q, v, work) = self.state(s);
        let acc = sys.accel(&q, &v)?;
        let power = if sys.has_slips() {
            sys.slip_power(&q, &v, &acc.lambda)
        } else {
            Float::new(sys.prec)
        };
        Ok(Sample {
            t,
            q,
            v,
            qdd: acc.qdd,
            lambda: acc.lambda,
            work,
            power,
        })
    }

    /// The time at the end of the piece.
    fn t_end(&self) -> Float {
        let p = self.len.prec();
        Float::with_val(p, &self.t0 + self.dt.eval(&self.len, p))
    }

    /// s where t(s) = tau, bracketed among the points first.
    fn invert_at(&self, tau: &Float) -> Float {
        let p = tau.prec();
        let k = self.nodes.partition_point(|(_, smp)| smp.t < *tau);
        let lo = match k {
            0 => (Float::new(p), self.t0.clone()),
            _ => (self.nodes[k - 1].0.clone(), self.nodes[k - 1].1.t.clone()),
        };
        let hi = match self.nodes.get(k) {
            Some((s, smp)) => (s.clone(), smp.t.clone()),
            None => (self.len.clone(), self.t_end()),
        };
        self.invert(tau, &lo, &hi)
    }

    /// s(t) on [t0, t1] as an interpolant (None: it does not converge to
    /// `tol` L with the points of `roots`), without the trailing
    /// coefficients whose sum stays below that tolerance.
    fn inverse(&self, roots: &Roots, t1: &Float, tol: &Float) -> Option<ChebFit> {
        let p = self.len.prec();
        let ts = ChebFit::points(&self.t0, t1, roots, p);
        let ss: Vec<Float> = ts.iter().map(|t| self.invert_at(t)).collect();
        let mut f = ChebFit::from_values(&self.t0, t1, roots, p, &ss);
        if !within(&f, tol, &self.len, &mut 0) {
            return None;
        }
        let each = Float::with_val(p, &self.len * tol) / (roots.n() as u64);
        while f.c.len() > 2
            && f.c
                .last()
                .is_some_and(|c| c.cmp_abs(&each) == Some(std::cmp::Ordering::Less))
        {
            f.c.pop();
        }
        Some(f)
    }

    /// s in [0, L] where t(s) = tau (t increasing in s): Newton's method in
    /// f64 from the bracket's linear interpolation, then at full precision
    /// (each step on one basis) until the step is below 2^(−p/2) L.
    fn invert(&self, tau: &Float, lo: &(Float, Float), hi: &(Float, Float)) -> Float {
        let p = tau.prec();
        let mut sc = self.scratch.borrow_mut();
        let (low, full) = &mut *sc;
        let target = Float::with_val(p, tau - &self.t0);
        let (a, b) = (lo.0.to_f64(), hi.0.to_f64());
        let (ta, tb) = (lo.1.to_f64(), hi.1.to_f64());
        let len = self.len.to_f64();
        let tg = target.to_f64();
        let mut s = if tb > ta {
            a + (b - a) * ((tau.to_f64() - ta) / (tb - ta))
        } else {
            a
        };
        for _ in 0..30 {
            let f = ChebFit::eval_f64(&self.dt64, 0.0, len, s) - tg;
            let d = ChebFit::eval_f64(&self.rate64, 0.0, len, s);
            let step = f / d;
            if !step.is_finite() {
                break;
            }
            s = (s - step).clamp(a, b);
            if step.abs() <= 1e-15 * len {
                break;
            }
        }
        // precision doubling: one step on each lower copy, then full steps
        let mut s = Float::with_val(p, s);
        for (q, dt, rate) in &self.lower {
            let sq = Float::with_val(*q, &s);
            let zero = Float::new(*q);
            let basis = &mut *low;
            ChebFit::basis_into(&zero, &dt.b, &sq, dt.c.len(), *q, basis);
            let f = dt.dot(basis) - Float::with_val(*q, &target);
            let step = f / rate.dot(basis);
            if step.is_finite() {
                s -= &step;
                s.assign(s.clone().max(&lo.0).min(&hi.0));
            }
        }
        let zero = Float::new(p);
        let stop = Float::with_val(p, &self.len) >> (p as i32 / 2 + 4);
        let n = self.dt.c.len();
        for _ in 0..20 {
            let basis = &mut *full;
            ChebFit::basis_into(&zero, &self.len, &s, n, p, basis);
            let f = self.dt.dot(basis) - &target;
            let step = f / self.rate.dot(basis);
            if !step.is_finite() {
                break;
            }
            s -= &step;
            s.assign(s.clone().max(&lo.0).min(&hi.0));
            if step.abs() <= stop {
                break;
            }
        }
        s
    }

    /// The first root in (lo, hi) of a watched function, from its
    /// interpolant over the points (its values `vals` at the points,
    /// ascending), corrected once by the exact value.
    fn root(
        &self,
        sys: &mut System,
        su: &Setup,
        ev: &Event,
        vals: &[Float],
        lo: &Float,
        hi: &Float,
    ) -> Result<(Float, Sample, Float)> {
        let p = sys.prec;
        // the interpolant wants the values in point order (descending s)
        let desc: Vec<Float> = vals.iter().rev().cloned().collect();
        let zero = Float::new(p);
        let fit = ChebFit::from_values(&zero, &self.len, su.roots, p, &desc);
        let d = fit.derivative();
        // bisection at 64 bits to a seed, then Newton at full precision
        let f64fit = fit.rounded(64);
        let mut a = Float::with_val(64, lo);
        let mut b = Float::with_val(64, hi);
        let fa = f64fit.eval(&a, 64);
        let neg_a = fa.is_sign_negative();
        for _ in 0..60 {
            let mid = Float::with_val(64, &a + &b) >> 1;
            if f64fit.eval(&mid, 64).is_sign_negative() == neg_a {
                a = mid;
            } else {
                b = mid;
            }
        }
        let mut s = Float::with_val(p, &a + &b) >> 1;
        let stop = Float::with_val(p, &self.len) >> (p as i32 - 8);
        for _ in 0..40 {
            let step = fit.eval(&s, p) / d.eval(&s, p);
            s -= &step;
            if !step.is_finite() {
                break;
            }
            if step.abs() <= stop {
                break;
            }
        }
        if !s.is_finite() {
            s = Float::with_val(p, &a + &b) >> 1;
        }
        s.assign(s.clone().max(lo).min(hi));
        // one correction by the exact value
        let smp = self.sample(sys, &s)?;
        let g = watch_value(&ev.watch, &smp);
        let dg = d.eval(&s, p);
        let ds = g / dg;
        let smp = if ds.is_finite() && !ds.is_zero() {
            let s2 = Float::with_val(p, &s - &ds);
            if s2 >= *lo && s2 <= *hi {
                s = s2;
                self.sample(sys, &s)?
            } else {
                smp
            }
        } else {
            smp
        };
        let t_err = Float::with_val(p, ds.abs_ref()) * self.rate.eval(&s, p)
            + Float::with_val(p, &su.sc.ts * su.tol);
        let t_err = if t_err.is_finite() {
            t_err
        } else {
            Float::with_val(p, &su.sc.ts * su.tol)
        };
        Ok((s, smp, t_err))
    }
}

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
    let d =
        Float::with_val(p, s.v[ith].square_ref()) / (acc * 2u32 + Float::with_val(p, 1e-300f64));
    Float::with_val(p, cap).min(&(d * 1.5f64))
}

/// Interior samples per gap between two points where a watched function's
/// interpolant is looked at too (a graze that crosses zero and comes back
/// between two points).
const BETWEEN: usize = 4;

/// The Chebyshev coefficients, in f64, of the interpolant of values at the
/// N points (`asc`: ascending s, i.e. the points in reverse order), by the
/// direct cosine sum (`cos[m]` = cos(mπ/2N), m < 4N).
fn coeffs64(asc: &[Float], cos: &[f64]) -> Vec<f64> {
    let n = asc.len();
    let f: Vec<f64> = asc.iter().rev().map(Float::to_f64).collect();
    (0..n)
        .map(|k| {
            // the angle index k(2j + 1) mod 4N, stepped by 2k < 4N
            let mut sum = 0.0;
            let mut m = k;
            for fj in &f {
                sum += fj * cos[m];
                m += 2 * k;
                if m >= 4 * n {
                    m -= 4 * n;
                }
            }
            let c = 2.0 * sum / n as f64;
            if k == 0 {
                c / 2.0
            } else {
                c
            }
        })
        .collect()
}

/// The first sign change of a watched function over the piece: from its
/// value at s = 0 (None: on its boundary there, not watched), over the
/// points — and [`BETWEEN`] samples of its interpolant `c64` in each gap,
/// where values below 10^−12 of the largest count as 0 — to its value at
/// the end.
fn first_bracket(
    nodes: &[&Float],
    len: &Float,
    start: Option<&Float>,
    vals: &[Float],
    end: &Float,
    c64: &[f64],
) -> Option<(Float, Float)> {
    let p = len.prec();
    let lenf = len.to_f64();
    let big = vals.iter().map(|v| v.to_f64().abs()).fold(0.0, f64::max);
    let floor = 1e-12 * big;
    // the sequence of (s, sign, the point itself) with the interpolant's
    // samples between points
    let mut seq: Vec<(f64, bool, Option<&Float>)> =
        Vec::with_capacity((BETWEEN + 1) * vals.len() + 2);
    let zero = Float::new(p);
    if let Some(g) = start.filter(|g| !g.is_zero()) {
        seq.push((0.0, g.is_sign_negative(), Some(&zero)));
    }
    let mut last = 0.0;
    let mut first_point = true;
    let points = nodes.iter().copied().zip(vals).chain([(len, end)]);
    for (s, g) in points {
        let sf = s.to_f64();
        if !first_point {
            for i in 1..=BETWEEN {
                let x = last + (sf - last) * i as f64 / (BETWEEN + 1) as f64;
                let v = ChebFit::eval_f64(c64, 0.0, lenf, x);
                if v.abs() > floor {
                    seq.push((x, v < 0.0, None));
                }
            }
        }
        first_point = false;
        last = sf;
        if !g.is_zero() {
            seq.push((sf, g.is_sign_negative(), Some(s)));
        }
    }
    let at = |(x, _, s): &(f64, bool, Option<&Float>)| match s {
        Some(s) => (*s).clone(),
        None => Float::with_val(p, *x),
    };
    seq.windows(2)
        .find(|w| w[0].1 != w[1].1)
        .map(|w| (at(&w[0]), at(&w[1])))
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
        };
        events
            .iter()
            .map(|e| {
                let g = watch_value(&e.watch, &smp0);
                (Float::with_val(p, g.abs_ref()) > start.snap).then_some(g)
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
        let brackets: Vec<Option<(Float, Float)>> = (0..events.len())
            .map(|k| {
                if events[k].terminal {
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
        for (i, tau) in times[next..next + count].iter().enumerate() {
            if i % 64 == 0 {
                crate::cancel::check()?;
            }
            let tau = Float::with_val(p, tau);
            let s = match &inverse {
                Some(f) => f.eval(&tau, p).max(&Float::new(p)).min(&pc.len),
                None => pc.invert_at(&tau),
            };
            let mut smp = if full {
                pc.sample(sys, &s)?
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
    use crate::integrate::solve::{self, Opts};
    use crate::mechanics::system::{SlipTerm, StackModel, Tangent};
    use crate::model::{Contact, Ideal};

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
                let (a, ab) = sys.accel_pair(&q, 0).unwrap();
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
    /// points is found by the samples of its interpolant between them.
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
        let g = |x: &Float| -> Float { Float::with_val(P, (x.to_f64() - c).powi(2) - d) };
        let vals: Vec<Float> = asc.iter().map(|x| g(x)).collect();
        assert!(vals.iter().all(|v| v.is_sign_positive()));
        let cos: Vec<f64> = (0..4 * n)
            .map(|m| (m as f64 * std::f64::consts::PI / (2 * n) as f64).cos())
            .collect();
        let c64 = coeffs64(&vals, &cos);
        let end = g(&len);
        let start = g(&Float::new(P));
        let (a, b) =
            first_bracket(&asc, &len, Some(&start), &vals, &end, &c64).expect("the graze is seen");
        let root = c - d.sqrt();
        assert!(a.to_f64() <= root && root <= b.to_f64(), "{a} {b} {root}");
        assert!(a.to_f64() >= lo && b.to_f64() <= hi);
        // without the samples between points there is no sign change
        assert!(first_bracket(&asc, &len, Some(&start), &vals, &end, &[0.0]).is_none());
    }

    /// A start at t = 0 with nothing dissipated and no snapping.
    fn at_zero<'a>(q: &'a [Float], v: &'a [Float]) -> Start<'a> {
        Start {
            t: Float::new(P),
            q,
            v,
            work: Float::new(P),
            snap: Float::new(P),
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
