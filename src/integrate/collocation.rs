//! Gauss–Legendre collocation (an implicit Runge–Kutta method of s stages
//! and order 2s) on `rug::Float`: the second, independent integrator of the
//! motion with friction.
//!
//! It shares nothing with [`super::gbs`] but the right-hand side: the stage
//! equations K_i = f(y0 + h Σ_j a_ij K_j) are solved by fixed-point
//! iteration to well below the tolerance, the new state is y0 + h Σ b_j K_j,
//! and the local error is estimated by step doubling (one step of h against
//! two of h/2, whose difference is (2^{2s} − 1) times the error of the two
//! half steps, which are kept). Nodes c_i = (1 + x_i)/2 from the Gauss
//! points x_i of [`crate::numeric::gauss::GaussLegendre`]; weights b_i =
//! w_i/2; a_ij = ∫_0^{c_i} ℓ_j(τ) dτ (ℓ_j the Lagrange basis on the nodes),
//! computed by the same Gauss rule, exact for these polynomials.
//!
//! Accuracy kind: *estimated*, like GBS; the two are compared on the same
//! motion (`tests/friction.rs`, `cylroll verify`).

use super::gbs::{Rhs, Stats, Step, Stepper};
use crate::error::{Error, Result};
use crate::numeric::gauss::GaussLegendre;
use rug::{Assign, Float};

/// The integrator.
#[derive(Debug, Clone)]
pub struct Collocation {
    prec: u32,
    tol: Float,
    h: Float,
    s: usize,
    b: Vec<Float>,
    a: Vec<Vec<Float>>,
    stats: Stats,
}

impl Collocation {
    /// s stages (order 2s) at `prec` bits, local tolerance `tol`, first step `h0`.
    pub fn new(prec: u32, tol: Float, h0: Float, s: usize) -> Self {
        let s = s.max(2);
        let gl = GaussLegendre::new(s, prec + 32);
        let p = prec;
        // all nodes on [−1, 1], ascending
        let mut xs: Vec<(Float, Float)> = Vec::with_capacity(s);
        for (x, w) in gl.x.iter().zip(&gl.w) {
            if x.is_zero() {
                xs.push((Float::with_val(p, x), Float::with_val(p, w)));
            } else {
                xs.push((Float::with_val(p, x), Float::with_val(p, w)));
                xs.push((-Float::with_val(p, x), Float::with_val(p, w)));
            }
        }
        xs.sort_by(|u, v| u.0.partial_cmp(&v.0).unwrap_or(std::cmp::Ordering::Equal));
        let c: Vec<Float> = xs
            .iter()
            .map(|(x, _)| (Float::with_val(p, x) + 1u32) / 2u32)
            .collect();
        let b: Vec<Float> = xs
            .iter()
            .map(|(_, w)| Float::with_val(p, w) / 2u32)
            .collect();
        let ell = |j: usize, x: &Float| -> Float {
            let mut v = Float::with_val(p, 1u32);
            for m in 0..s {
                if m != j {
                    v *= Float::with_val(p, x - &c[m]);
                    v /= Float::with_val(p, &c[j] - &c[m]);
                }
            }
            v
        };
        let mut a = vec![vec![Float::new(p); s]; s];
        for i in 0..s {
            for (j, aij) in a[i].iter_mut().enumerate() {
                let mut acc = Float::new(p);
                for k in 0..s {
                    let x = Float::with_val(p, &c[i] * &c[k]);
                    acc += Float::with_val(p, &b[k] * ell(j, &x));
                }
                aij.assign(acc * &c[i]);
            }
        }
        Collocation {
            prec,
            tol,
            h: h0,
            s,
            b,
            a,
            stats: Stats::default(),
        }
    }

    /// One collocation step of exactly h; None if the stage iteration does
    /// not converge (the caller shrinks h).
    fn one<R: Rhs>(
        &mut self,
        rhs: &mut R,
        y0: &[Float],
        f0: &[Float],
        h: &Float,
    ) -> Result<Option<Vec<Float>>> {
        let p = self.prec;
        let n = y0.len();
        let s = self.s;
        let mut k: Vec<Vec<Float>> = vec![f0.to_vec(); s];
        let mut knew = vec![vec![Float::new(p); n]; s];
        let mut yi = vec![Float::new(p); n];
        let lim = Float::with_val(p, &self.tol >> 8u32);
        for _ in 0..80 {
            let mut worst = Float::new(p);
            for i in 0..s {
                for (m, y) in yi.iter_mut().enumerate() {
                    let mut acc = Float::new(p);
                    for (aij, kj) in self.a[i].iter().zip(&k) {
                        acc += aij * &kj[m];
                    }
                    y.assign(&acc * h);
                    *y += &y0[m];
                }
                rhs.eval(&yi, &mut knew[i])?;
                self.stats.evals += 1;
                for m in 0..n {
                    let d = Float::with_val(p, &knew[i][m] - &k[i][m]) * h;
                    let sc = Float::with_val(p, y0[m].abs_ref()) + 1u32;
                    let r = Float::with_val(p, d.abs_ref()) / sc;
                    if r > worst {
                        worst = r;
                    }
                }
            }
            std::mem::swap(&mut k, &mut knew);
            if !worst.is_finite() {
                return Ok(None);
            }
            if worst <= lim {
                let mut y1 = y0.to_vec();
                for (m, y) in y1.iter_mut().enumerate() {
                    let mut acc = Float::new(p);
                    for (bj, kj) in self.b.iter().zip(&k) {
                        acc += bj * &kj[m];
                    }
                    *y += acc * h;
                }
                return Ok(Some(y1));
            }
        }
        Ok(None)
    }

    /// Two half steps (the accepted method).
    fn two<R: Rhs>(
        &mut self,
        rhs: &mut R,
        y0: &[Float],
        f0: &[Float],
        h: &Float,
    ) -> Result<Option<Vec<Float>>> {
        let half = Float::with_val(self.prec, h / 2u32);
        let Some(ym) = self.one(rhs, y0, f0, &half)? else {
            return Ok(None);
        };
        let mut fm = vec![Float::new(self.prec); y0.len()];
        rhs.eval(&ym, &mut fm)?;
        self.stats.evals += 1;
        self.one(rhs, &ym, &fm, &half)
    }
}

impl Stepper for Collocation {
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
        let p = self.prec;
        if self.h > *hmax {
            self.h.assign(hmax);
        }
        let order = 2 * self.s as i32;
        for _ in 0..200 {
            let h = self.h.clone();
            let big = self.one(rhs, y0, f0, &h)?;
            let small = match big {
                Some(_) => self.two(rhs, y0, f0, &h)?,
                None => None,
            };
            let (Some(big), Some(small)) = (big, small) else {
                self.stats.rejected += 1;
                self.h /= 4u32;
                continue;
            };
            // error of the two half steps ≈ (small − big)/(2^{2s} − 1)
            let mut e = 0.0f64;
            for (m, (a, b)) in small.iter().zip(&big).enumerate() {
                let sc = (Float::with_val(64, y0[m].abs_ref()) + 1u32) * &self.tol;
                let d = Float::with_val(64, a - b) / sc;
                let r = d.to_f64() / (2f64.powi(order) - 1.0);
                e = e.max(r.abs());
            }
            let fac = if e <= 0.0 {
                4.0
            } else {
                (0.8 * e.powf(-1.0 / (order + 1) as f64)).clamp(0.2, 4.0)
            };
            if e <= 1.0 {
                self.stats.steps += 1;
                let hn = Float::with_val(p, &h * fac);
                self.h = hn;
                return Ok(Step {
                    h,
                    y: small,
                    column: 0,
                });
            }
            self.stats.rejected += 1;
            self.h = Float::with_val(p, &h * fac.min(0.9));
        }
        Err(Error::NotConverged {
            quantity: "collocation step".into(),
            requested: 0,
            reached: "the step size collapsed".into(),
            detail: "Gauss-Legendre collocation could not meet its tolerance".into(),
        })
    }
    fn fixed_step<R: Rhs>(
        &mut self,
        rhs: &mut R,
        y0: &[Float],
        f0: &[Float],
        h: &Float,
        _column: usize,
    ) -> Result<Vec<Float>> {
        self.two(rhs, y0, f0, h)?
            .ok_or_else(|| Error::NotConverged {
                quantity: "collocation step".into(),
                requested: 0,
                reached: "the stage iteration did not converge".into(),
                detail: "inside an event's step".into(),
            })
    }
}
