//! One piece of the angle: the state at its start and the Chebyshev
//! interpolants of θ̇², t, the moving rates and coordinates and the work
//! on it ([`Piece`]), built from the KKT solves at its points by
//! [`attempt`], which also judges whether the interpolants converged; the
//! state and samples anywhere on the piece.

use super::dependents::{fill_dependents, Dependent};
use super::time::{lower_copies, Lower};
use super::Settings;
use crate::error::Result;
use crate::integrate::solve::Sample;
use crate::mechanics::system::{self as sy, Accel, System};
use crate::numeric::cheb::fixed_sums::LazySums;
use crate::numeric::cheb::{ChebFit, Roots};
use rug::{Assign, Float};

/// Extra bits of the m = 2 quadrature for u.
pub(super) const REST_GUARD: u32 = 48;

/// One piece: the state at s = 0 and the interpolants on [0, L].
pub(super) struct Piece {
    m: u32,
    dir: i32,
    pub(super) len: Float,
    pub(super) t0: Float,
    q0: Vec<Float>,
    v0: Vec<Float>,
    work0: Float,
    /// t(s) − t0.
    pub(super) dt: ChebFit,
    /// dt/ds = m/√w (u = θ̇² = s^(2(m−1)) w; θ̇ = σ s^(m−1) m/rate).
    pub(super) rate: ChebFit,
    /// q̇_i(s) − q̇_i(0) of the coordinates that move besides θ.
    vel: Vec<(usize, ChebFit)>,
    /// q_i(s) − q_i(0).
    pos: Vec<(usize, ChebFit)>,
    /// W(s) − W(0) (None without slipping contacts).
    work: Option<ChebFit>,
    deps: Vec<Dependent>,
    /// t(s) − t0 and dt/ds at 128, 256, … bits up to 3p/4 (and one near
    /// p/2 where it pays), their coefficients cut where they fall below the
    /// precision (the first Newton steps of an inversion).
    pub(super) lower: Vec<Lower>,
    /// t(s) − t0 and dt/ds in f64 (Newton seeds), both scaled by
    /// 2^−`t64_exp` (the exponent of t(s) − t0's largest coefficient), so
    /// that they hold in any unit of time.
    pub(super) dt64: Vec<f64>,
    pub(super) rate64: Vec<f64>,
    pub(super) t64_exp: i32,
    /// The samples at the points, in ascending s, with their s.
    pub(super) nodes: Vec<(Float, Sample)>,
    /// The most coefficients any interpolant needed (above its tolerance).
    pub(super) used: usize,
    /// Bases of the inversions' Newton steps (lower precisions, full).
    pub(super) scratch: std::cell::RefCell<(Vec<Float>, Vec<Float>)>,
    /// The interpolants in fixed point for output rows.
    fixed: LazySums,
    /// t(s) − t0 and dt/ds in fixed point for the inversions.
    pub(super) fixed_time: LazySums,
}

pub(super) enum Attempt {
    Done(Box<Piece>),
    /// The interpolants did not converge: a shorter piece.
    Shorter,
    /// θ̇ vanishes inside (or w is not positive): the route declines.
    Decline,
}

/// The precision the fixed-point sums of a piece's interpolants are built
/// for ([`LazySums`]: the rows, their times and the state at the last time
/// asked, values only read): 16 bits beyond the interpolants' tolerance
/// tol = 2^−b, at most the working precision p, in fewer limbs than p would
/// take (at 30 digits 4 instead of 5). Each interpolant is summed in its
/// own scale, within 2^−(b+6)·Σ|c_k| of the exact sum: 2^−6 of its
/// tolerance, which is relative to its scale too (`within`), and far below
/// the rows' own error estimates (a few units of 2^−(b−16)).
pub(super) fn fixed_prec(tol: &Float, p: u32) -> u32 {
    let b = tol.get_exp().map_or(p, |e| (1 - e).max(1) as u32);
    (b + 16).min(p)
}

/// Whether the fit's last coefficients are below tol·(max |f| + floor);
/// `used` grows to the number of coefficients above that level.
pub(super) fn within(f: &ChebFit, tol: &Float, floor: &Float, used: &mut usize) -> bool {
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

/// a and b of q̈ = a + b θ̇² (and of λ) at angle θ: two KKT solves, the
/// second at θ̇ = 2^k ([`System::accel_pair`]; b is their difference over
/// 4^k, exactly).
fn probe(sys: &mut System, q: &mut [Float], th: &Float, k: i32) -> Result<(Accel, Accel)> {
    q[sy::th(0)].assign(th);
    let (a0, mut a1) = sys.accel_pair(q, 0, k)?;
    for (x, y) in a1.qdd.iter_mut().zip(&a0.qdd) {
        *x -= y;
        *x >>= 2 * k;
    }
    for (x, y) in a1.lambda.iter_mut().zip(&a0.lambda) {
        *x -= y;
        *x >>= 2 * k;
    }
    Ok((a0, a1))
}

/// k with 2^k the power of two nearest the natural rate 1/ts (within a
/// factor 2): where [`probe`] asks for the velocity terms.
pub(super) fn rate_exp(ts: &Float) -> i32 {
    ts.get_exp().map_or(0, |e| 1 - e)
}

/// x + y·u for vectors.
fn affine(x: &[Float], y: &[Float], u: &Float) -> Vec<Float> {
    x.iter()
        .zip(y)
        .map(|(a, b)| Float::with_val(a.prec(), a + Float::with_val(a.prec(), b * u)))
        .collect()
}

pub(super) struct Setup<'a> {
    pub(super) roots: &'a Roots,
    /// The same points with twiddles at p + [`REST_GUARD`] (+ 32) bits, for
    /// a start from rest.
    pub(super) rest_roots: Option<&'a Roots>,
    pub(super) tol: &'a Float,
    pub(super) sc: &'a Settings,
    pub(super) moving: Vec<usize>,
    pub(super) deps: Vec<Dependent>,
    /// Whether a watched function reads a moving coordinate: only then do
    /// the samples at the points carry their positions and the work (else
    /// those of s = 0; the samples serve the watched functions and the
    /// times).
    pub(super) node_positions: bool,
}

#[allow(clippy::too_many_arguments)]
pub(super) fn attempt(
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
    let fx = fixed_prec(su.tol, p);
    let n = su.roots.n();
    let ith = sy::th(0);
    let zero = Float::new(p);
    let pts = ChebFit::points(&zero, len, su.roots, p);
    let th0 = &q0[ith];
    let mut used = 0usize;
    let mut parts = Vec::with_capacity(n);
    let mut qp = q0.to_vec();
    let k = rate_exp(&su.sc.ts);
    for s in &pts {
        crate::cancel::check()?;
        parts.push(probe(sys, &mut qp, &theta_at(th0, dir, m, s), k)?);
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
    crate::cancel::check()?;
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
    crate::cancel::check()?;
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
    crate::cancel::check()?;
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
    let inv_ts = Float::with_val(p, su.sc.ts.recip_ref());
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
        crate::cancel::check()?;
        let f: Vec<Float> = (0..n)
            .map(|k| {
                let (a, b) = &parts[k];
                let acc = Float::with_val(p, &a.qdd[i] + Float::with_val(p, &b.qdd[i] * &u[k]));
                acc * &rate[k]
            })
            .collect();
        let fit = ChebFit::from_values(&zero, len, su.roots, p, &f);
        // a rate's floor: r/ts for a length, 1/ts for an angle (φ1, ψ2)
        let unit = if sy::is_length(i) { &vscale } else { &inv_ts };
        if !within(
            &fit,
            su.tol,
            &Float::with_val(p, unit * &inv_len),
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
        crate::cancel::check()?;
        let f: Vec<Float> = (0..n)
            .map(|k| Float::with_val(p, &vnodes[k][i] * &rate[k]))
            .collect();
        let fit = ChebFit::from_values(&zero, len, su.roots, p, &f);
        let one = Float::with_val(p, 1u32);
        let unit = if sy::is_length(i) { &su.sc.r } else { &one };
        if !within(
            &fit,
            su.tol,
            &Float::with_val(p, unit * &inv_len),
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
                trig: Vec::new(),
                energy: None,
            },
        ));
    }
    // the f64 seeds' time scale
    let t64_exp = crate::numeric::max_exp(&dt.c).unwrap_or(0);
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
        lower: lower_copies(&dt, &rfit, p, fx),
        used,
        scratch: Default::default(),
        fixed: LazySums::at(fx),
        fixed_time: LazySums::at(fx),
        dt64: dt
            .c
            .iter()
            .map(|c| crate::numeric::scaled_f64(c, t64_exp))
            .collect(),
        rate64: rfit
            .c
            .iter()
            .map(|c| crate::numeric::scaled_f64(c, t64_exp))
            .collect(),
        t64_exp,
        nodes,
    })))
}

impl Piece {
    /// The interpolants in the order [`Piece::state`] reads their sums:
    /// the rate, the velocities, the positions, t (not for a row, whose
    /// time is the one asked), the work.
    fn fits(&self, with_time: bool) -> Vec<&ChebFit> {
        let mut f = vec![&self.rate];
        f.extend(self.vel.iter().map(|(_, f)| f));
        f.extend(self.pos.iter().map(|(_, f)| f));
        if with_time {
            f.push(&self.dt);
        }
        f.extend(self.work.as_ref());
        f
    }

    /// The state (t, q, q̇, W) at s: every interpolant on one basis;
    /// `row`: the time of a state only read (an output row at the time
    /// t(s) = τ asked), whose sums are taken in fixed point where it
    /// applies ([`LazySums`]: within the interpolants' tolerance, several
    /// times cheaper than MPFR's) and whose t is τ.
    fn state(&self, s: &Float, row: Option<&Float>) -> (Float, Vec<Float>, Vec<Float>, Float) {
        let p = s.prec();
        let ith = sy::th(0);
        let zero = Float::new(p);
        let fits = self.fits(row.is_none());
        let mut sums = vec![Float::new(p); fits.len()];
        if !(row.is_some() && self.fixed.eval(&fits, &zero, &self.len, s, &mut sums)) {
            let mut sc = self.scratch.borrow_mut();
            let basis = &mut sc.1;
            ChebFit::basis_into(&zero, &self.len, s, self.dt.c.len(), p, basis);
            for (o, f) in sums.iter_mut().zip(&fits) {
                *o = f.dot(basis);
            }
        }
        let mut sums = sums.into_iter();
        let mut next = || sums.next().unwrap_or_else(|| Float::new(p));
        let mut q = self.q0.clone();
        let mut v = self.v0.clone();
        q[ith] = theta_at(&self.q0[ith], self.dir, self.m, s);
        let mut thd = Float::with_val(p, self.m) / next();
        if self.m == 2 {
            thd *= s;
        }
        v[ith] = thd * self.dir;
        for (i, _) in &self.vel {
            v[*i] = Float::with_val(p, &self.v0[*i] + next());
        }
        for (i, _) in &self.pos {
            q[*i] = Float::with_val(p, &self.q0[*i] + next());
        }
        fill_dependents(&self.deps, &self.q0, &mut q, &mut v);
        let t = match row {
            Some(tau) => Float::with_val(p, tau),
            None => Float::with_val(p, &self.t0 + next()),
        };
        let work = match &self.work {
            Some(_) => Float::with_val(p, &self.work0 + next()),
            None => self.work0.clone(),
        };
        (t, q, v, work)
    }

    /// A sample at s with t and θ only (every other value that of s = 0,
    /// no rates, forces or work): for [`run`](super::run) without `full` rows.
    pub(super) fn theta_sample(&self, s: &Float) -> Sample {
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
            trig: Vec::new(),
            energy: None,
        }
    }

    /// The full sample at s (one KKT solve).
    pub(super) fn sample(&self, sys: &mut System, s: &Float) -> Result<Sample> {
        self.sample_as(sys, s, None)
    }

    /// [`Piece::sample`] for an output row at the time τ = t(s), which
    /// nothing is computed from: the interpolants summed in fixed point
    /// (within their tolerance, far below the row's precision, several
    /// times cheaper), t(s) not summed (the row's time is τ).
    pub(super) fn row_sample(&self, sys: &mut System, s: &Float, tau: &Float) -> Result<Sample> {
        self.sample_as(sys, s, Some(tau))
    }

    fn sample_as(&self, sys: &mut System, s: &Float, row: Option<&Float>) -> Result<Sample> {
        let (t, q, v, work) = self.state(s, row);
        let acc = sys.accel(&q, &v)?;
        let power = if sys.has_slips() {
            sys.slip_power(&q, &v, &acc.lambda)
        } else {
            Float::new(sys.prec)
        };
        // a row's point is made after the run: it finds these again, and
        // the energy from the mass matrix the KKT solve left (the same bits
        // as building the matrix again then)
        let (trig, energy) = match row {
            Some(_) => (sys.trig_kept(&q), Some(sys.energy(&q, &v))),
            None => (Vec::new(), None),
        };
        Ok(Sample {
            t,
            q,
            v,
            qdd: acc.qdd,
            lambda: acc.lambda,
            work,
            power,
            trig,
            energy,
        })
    }

    /// The time at the end of the piece.
    pub(super) fn t_end(&self) -> Float {
        let p = self.len.prec();
        Float::with_val(p, &self.t0 + self.dt.eval(&self.len, p))
    }
}
