//! Gragg–Bulirsch–Stoer extrapolation on `rug::Float` with error estimation,
//! step-size and order control (after Hairer, Nørsett & Wanner, *Solving
//! Ordinary Differential Equations I*, sec. II.9, code ODEX).
//!
//! One step of size H: Gragg's modified midpoint rule with n_j = 2j substeps
//! (the harmonic sequence), z_{i+1} = z_{i−1} + 2h f(z_i), gives T_{j,1}
//! whose error has an expansion in even powers of h = H/n_j; the
//! Aitken–Neville tableau T_{j,l+1} = T_{j,l} + (T_{j,l} − T_{j−1,l}) /
//! ((n_j/n_{j−l})² − 1) eliminates them, so T_{j,j} has order 2j. The
//! difference T_{j,j} − T_{j,j−1}, measured against the tolerance, is the
//! error estimate; the step is accepted at the first column in the window
//! k−1, k, k+1 where it is ≤ 1, and the next step size and column are the
//! ones with the least work per unit step. Because the order is free, the
//! error can be driven to hundreds of digits at a cost that grows like the
//! square of the number of digits.
//!
//! Accuracy kind: *estimated* (local error per step below `tol` in the mixed
//! norm); the caller checks the global error by running at two precisions
//! and tolerances.

use crate::error::{Error, Result};
use rug::{Assign, Float};

/// A right-hand side y' = f(y) (autonomous).
pub trait Rhs {
    /// f(y) into `dy`.
    fn eval(&mut self, y: &[Float], dy: &mut [Float]) -> Result<()>;
}

/// Work counters.
#[derive(Debug, Clone, Default)]
pub struct Stats {
    /// Accepted steps.
    pub steps: u64,
    /// Rejected steps.
    pub rejected: u64,
    /// Evaluations of f.
    pub evals: u64,
    /// Largest column used in an accepted step.
    pub max_column: usize,
}

/// The integrator's settings and its state between steps.
#[derive(Debug, Clone)]
pub struct Gbs {
    /// Working precision (bits).
    pub prec: u32,
    /// Tolerance: a component's error is scaled by tol·(1 + |y|).
    pub tol: Float,
    /// Largest column (order 2·kmax).
    pub kmax: usize,
    /// Proposed size of the next step.
    pub h: Float,
    /// Proposed target column of the next step.
    pub k: usize,
    /// Work done.
    pub stats: Stats,
    seq: Vec<usize>,
    work: Vec<f64>,
}

/// An accepted step.
#[derive(Debug, Clone)]
pub struct Step {
    /// The step size taken.
    pub h: Float,
    /// y at the end of the step.
    pub y: Vec<Float>,
    /// The column at which it was accepted (order 2·column).
    pub column: usize,
}

impl Gbs {
    /// An integrator at `prec` bits with tolerance `tol`, first step `h0`,
    /// columns up to `kmax` (at least 3) and first target column `k0`.
    pub fn new(prec: u32, tol: Float, h0: Float, kmax: usize, k0: usize) -> Self {
        let kmax = kmax.max(3);
        let seq: Vec<usize> = (1..=kmax + 1).map(|j| 2 * j).collect();
        // A_j: evaluations for rows 1..j (f(y0) shared)
        let mut work = Vec::with_capacity(kmax + 1);
        let mut a = 1.0;
        for n in &seq {
            a += (*n - 1) as f64;
            work.push(a);
        }
        Gbs {
            prec,
            tol,
            kmax,
            h: h0,
            k: k0.clamp(2, kmax - 1),
            stats: Stats::default(),
            seq,
            work,
        }
    }

    /// Gragg's modified midpoint rule: n substeps of size H/n from y0
    /// (f0 = f(y0)).
    fn midpoint<R: Rhs>(
        &mut self,
        rhs: &mut R,
        y0: &[Float],
        f0: &[Float],
        big_h: &Float,
        n: usize,
    ) -> Result<Vec<Float>> {
        let p = self.prec;
        let h = Float::with_val(p, big_h / n as u32);
        let h2 = Float::with_val(p, &h * 2u32);
        let mut zprev: Vec<Float> = y0.to_vec();
        let mut z: Vec<Float> = y0
            .iter()
            .zip(f0)
            .map(|(y, f)| {
                let mut t = Float::with_val(p, y);
                t += &h * f;
                t
            })
            .collect();
        let mut fz = vec![Float::new(p); y0.len()];
        for _ in 1..n {
            rhs.eval(&z, &mut fz)?;
            self.stats.evals += 1;
            // z_{i+1} = z_{i−1} + 2h f(z_i), written over z_{i−1}
            for (zp, fi) in zprev.iter_mut().zip(&fz) {
                *zp += &h2 * fi;
            }
            std::mem::swap(&mut zprev, &mut z);
        }
        Ok(z)
    }

    /// The scaled error norm of `d` (a difference of two estimates) against
    /// y0 and y1: sqrt(mean((d_i / (tol (1 + max|y|)))²)).
    fn norm(&self, d: &[Float], y0: &[Float], y1: &[Float]) -> f64 {
        let p = 64;
        let mut s = 0.0f64;
        for i in 0..d.len() {
            let mut sc = Float::with_val(p, y0[i].abs_ref());
            let a1 = Float::with_val(p, y1[i].abs_ref());
            if a1 > sc {
                sc = a1;
            }
            sc += 1u32;
            sc *= &self.tol;
            let r = Float::with_val(p, &d[i] / &sc).to_f64();
            s += r * r;
        }
        (s / d.len() as f64).sqrt()
    }

    /// Builds the tableau up to `rows` rows (or until `stop` says so) and
    /// returns the rows' diagonal entries, errors and the last row.
    fn tableau<R: Rhs>(
        &mut self,
        rhs: &mut R,
        y0: &[Float],
        f0: &[Float],
        big_h: &Float,
        rows: usize,
        mut stop: impl FnMut(usize, f64) -> bool,
    ) -> Result<(Vec<Vec<Float>>, Vec<f64>)> {
        let p = self.prec;
        let mut prev: Vec<Vec<Float>> = Vec::new();
        let mut errs = vec![f64::INFINITY; rows + 1];
        for j in 1..=rows {
            let t1 = self.midpoint(rhs, y0, f0, big_h, self.seq[j - 1])?;
            let mut row: Vec<Vec<Float>> = Vec::with_capacity(j);
            row.push(t1);
            for l in 1..j {
                // T_{j,l+1} = T_{j,l} + (T_{j,l} − T_{j−1,l}) / ((n_j/n_{j−l})² − 1)
                let nj = self.seq[j - 1] as u64;
                let nl = self.seq[j - 1 - l] as u64;
                let denom = Float::with_val(p, nj * nj - nl * nl) / (nl * nl);
                let next: Vec<Float> = row[l - 1]
                    .iter()
                    .zip(&prev[l - 1])
                    .map(|(a, b)| {
                        let mut d = Float::with_val(p, a - b);
                        d /= &denom;
                        d += a;
                        d
                    })
                    .collect();
                row.push(next);
            }
            if j >= 2 {
                let d: Vec<Float> = row[j - 1]
                    .iter()
                    .zip(&row[j - 2])
                    .map(|(a, b)| Float::with_val(p, a - b))
                    .collect();
                errs[j] = self.norm(&d, y0, &row[j - 1]);
            }
            prev = row;
            if stop(j, errs[j]) {
                break;
            }
        }
        Ok((prev, errs))
    }

    /// One step of exactly `h` from y0 at a fixed column (no error control):
    /// the re-integration used to locate events inside an accepted step.
    pub fn fixed_step<R: Rhs>(
        &mut self,
        rhs: &mut R,
        y0: &[Float],
        f0: &[Float],
        h: &Float,
        column: usize,
    ) -> Result<Vec<Float>> {
        let (mut row, _) = self.tableau(rhs, y0, f0, h, column, |_, _| false)?;
        row.pop()
            .ok_or_else(|| Error::not_physical("empty extrapolation tableau"))
    }

    fn fac(err: f64, j: usize) -> f64 {
        if !err.is_finite() {
            return 0.1;
        }
        if err <= 0.0 {
            return 4.0;
        }
        let f = 0.94 * (0.65 / err).powf(1.0 / (2 * j - 1) as f64);
        f.clamp(0.1, 4.0)
    }

    /// One accepted step from y0 (f0 = f(y0)), no longer than `hmax`:
    /// rejected attempts are retried with a smaller step.
    ///
    /// Errors: from `rhs`; [`Error::NotConverged`] if the step size
    /// underflows.
    pub fn step<R: Rhs>(
        &mut self,
        rhs: &mut R,
        y0: &[Float],
        f0: &[Float],
        hmax: &Float,
    ) -> Result<Step> {
        let p = self.prec;
        if self.h > *hmax {
            self.h.assign(hmax);
        }
        let mut rejected_before = false;
        loop {
            let h = self.h.clone();
            let kc = self.k;
            let rows = (kc + 1).min(self.kmax);
            let seq = self.seq.clone();
            let n1 = seq[0] as f64;
            let (mut row, errs) = self.tableau(rhs, y0, f0, &h, rows, |j, err| {
                if j < 2 || j + 1 < kc {
                    return false;
                }
                if err <= 1.0 {
                    return true;
                }
                // convergence monitor: give up early when column k+1 cannot
                // plausibly reach the tolerance
                if j + 1 == kc {
                    let b = (seq[kc - 1] as f64 * seq[kc] as f64 / (n1 * n1)).powi(2);
                    return err > b;
                }
                if j == kc {
                    let b = (seq[kc] as f64 / n1).powi(2);
                    return err > b;
                }
                true
            })?;
            let j = row.len();
            let err = errs[j];
            // optimal step sizes and work per unit step of the columns seen
            let hopt = |i: usize| -> f64 { Self::fac(errs[i], i) };
            let w = |i: usize| -> f64 { self.work[i - 1] / hopt(i) };
            if err <= 1.0 {
                let y = row
                    .pop()
                    .ok_or_else(|| Error::not_physical("empty extrapolation tableau"))?;
                self.stats.steps += 1;
                self.stats.max_column = self.stats.max_column.max(j);
                // next column and step
                let (knew, fac) = if j > 2 && w(j - 1) < 0.8 * w(j) {
                    (j - 1, hopt(j - 1))
                } else if !rejected_before && j + 1 < self.kmax && (j == 2 || w(j) < 0.9 * w(j - 1))
                {
                    (j + 1, hopt(j) * self.work[j] / self.work[j - 1])
                } else {
                    (j, hopt(j))
                };
                let fac = if rejected_before { fac.min(1.0) } else { fac };
                self.k = knew.clamp(2, self.kmax - 1);
                self.h = Float::with_val(p, &h * fac);
                return Ok(Step { h, y, column: j });
            }
            self.stats.rejected += 1;
            rejected_before = true;
            let knew = if j > 2 && w(j - 1) < 0.8 * w(j) {
                j - 1
            } else {
                j.min(kc)
            };
            self.k = knew.clamp(2, self.kmax - 1);
            let fac = hopt(self.k.min(j).max(2)).min(0.9);
            self.h = Float::with_val(p, &h * fac);
            let tiny = Float::with_val(p, hmax.abs_ref()) >> (p as i32);
            if self.h <= tiny || self.h.is_zero() {
                return Err(Error::NotConverged {
                    quantity: "time step".into(),
                    requested: 0,
                    reached: "step size underflow".into(),
                    detail: format!("at column {j}, error estimate {err:.3e}"),
                });
            }
        }
    }
}

/// A one-step integrator with error control, as the event-locating driver
/// ([`super::solve`]) uses it: accepted steps, and re-integration from a
/// step's start over a given length to locate an event inside it.
pub trait Stepper {
    /// Working precision (bits).
    fn prec(&self) -> u32;
    /// The local tolerance.
    fn tol(&self) -> &Float;
    /// Work done.
    fn stats(&self) -> Stats;
    /// One accepted step from y0 (f0 = f(y0)), no longer than `hmax`.
    fn step<R: Rhs>(
        &mut self,
        rhs: &mut R,
        y0: &[Float],
        f0: &[Float],
        hmax: &Float,
    ) -> Result<Step>;
    /// The method of the accepted step `column` over exactly `h` from y0.
    fn fixed_step<R: Rhs>(
        &mut self,
        rhs: &mut R,
        y0: &[Float],
        f0: &[Float],
        h: &Float,
        column: usize,
    ) -> Result<Vec<Float>>;
}

impl Stepper for Gbs {
    fn prec(&self) -> u32 {
        self.prec
    }
    fn tol(&self) -> &Float {
        &self.tol
    }
    fn stats(&self) -> Stats {
        self.stats.clone()
    }
    fn step<R: Rhs>(
        &mut self,
        rhs: &mut R,
        y0: &[Float],
        f0: &[Float],
        hmax: &Float,
    ) -> Result<Step> {
        Gbs::step(self, rhs, y0, f0, hmax)
    }
    fn fixed_step<R: Rhs>(
        &mut self,
        rhs: &mut R,
        y0: &[Float],
        f0: &[Float],
        h: &Float,
        column: usize,
    ) -> Result<Vec<Float>> {
        Gbs::fixed_step(self, rhs, y0, f0, h, column)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// y'' = −y as a first-order system: y = (cos t, −sin t).
    struct Osc;
    impl Rhs for Osc {
        fn eval(&mut self, y: &[Float], dy: &mut [Float]) -> Result<()> {
            dy[0].assign(&y[1]);
            dy[1].assign(-&y[0]);
            Ok(())
        }
    }

    #[test]
    fn harmonic_oscillator_to_many_digits() {
        for (prec, tol_bits) in [(128u32, 110i32), (400, 380)] {
            let tol = Float::with_val(prec, 1u32) >> tol_bits;
            let mut g = Gbs::new(prec, tol, Float::with_val(prec, 0.1), 60, 8);
            let mut y = vec![Float::with_val(prec, 1u32), Float::new(prec)];
            let mut t = Float::new(prec);
            let end = Float::with_val(prec, 10u32);
            let mut f = vec![Float::new(prec), Float::new(prec)];
            while t < end {
                Osc.eval(&y, &mut f).unwrap();
                let hmax = Float::with_val(prec, &end - &t);
                let s = g.step(&mut Osc, &y, &f, &hmax).unwrap();
                t += &s.h;
                y = s.y;
            }
            let exact = Float::with_val(prec, end.cos_ref());
            let err = Float::with_val(prec, &y[0] - &exact).abs();
            let bound = Float::with_val(prec, 1u32) >> (tol_bits - 12);
            assert!(err < bound, "prec {prec}: err {err:e}");
        }
    }
}
