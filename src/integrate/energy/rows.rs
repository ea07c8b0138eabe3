//! A trajectory's rows on the energy route: every column of a row of a
//! conservative phase as a closed form of δ = θ − θ0 ([`Route::columns_at`]),
//! the error δ's bound and the roundings carry into them
//! ([`Route::column_errors`]), and the ideal oracle's 13-column rows
//! ([`Route::row_estimates`]).

use super::{Engine, Route};
use crate::error::Result;
use crate::exact::Exact;
use crate::mechanics::dynamics::Dyn;
use crate::model::{Contact, Floor};
use crate::numeric::verify::Estimate;
use rug::Float;

/// Constants of the trajectory rows at one precision.
pub struct RowContext {
    p: u32,
    /// Natural scales of the 12 columns after t.
    scales: [Float; 12],
    /// √(r/g).
    ts: Float,
    /// r = r1 + r2.
    rr: Float,
    /// r1.
    r1: Float,
}

impl Route {
    /// The per-run constants of the trajectory rows at precision `p`.
    pub fn row_context(&self, p: u32) -> RowContext {
        let sf = self.scale_force(p);
        let ts = self.scale_time(p);
        let pr = self.work.params();
        let rr = Float::with_val(p, &pr.r());
        let r1 = Float::with_val(p, &pr.r1);
        let one = Float::with_val(p, 1u32);
        let inv_ts = Float::with_val(p, &one / &ts);
        let inv_ts2 = Float::with_val(p, &inv_ts / &ts);
        RowContext {
            p,
            scales: [
                one.clone(),
                inv_ts,
                inv_ts2,
                one.clone(),
                one,
                rr.clone(),
                rr.clone(),
                rr.clone(),
                sf.clone(),
                sf.clone(),
                sf.clone(),
                sf,
            ],
            ts,
            rr,
            r1,
        }
    }

    /// The estimates of one trajectory row at time `t` from δ and its bound.
    pub fn row_estimates(
        &mut self,
        t: &Exact,
        d: &Float,
        derr: &Float,
        ctx: &RowContext,
        floor: Floor,
        contact: Contact,
    ) -> Result<Vec<Estimate>> {
        let p = ctx.p;
        let tf = t.to_float(p);
        let (rr, r1) = (&ctx.rr, &ctx.r1);
        let e = self.engine(p)?;
        let st = e.dynm.state(d);
        let d2 = Float::with_val(p, d + derr);
        let st2 = e.dynm.state(&d2);
        let vals = |st: &crate::mechanics::dynamics::State, e: &Engine| -> Vec<Float> {
            let pos = e.dynm.positions_phi2(st, &tf);
            let f = e.dynm.forces(st);
            let x2 = Float::with_val(p, rr * &st.s) + &pos[0];
            let y2 = Float::with_val(p, rr * &st.c) + r1;
            vec![
                st.theta.clone(),
                st.thetadot.clone(),
                st.thetaddot.clone(),
                pos[1].clone(),
                pos[2].clone(),
                pos[0].clone(),
                x2,
                y2,
                f.f1,
                f.n1,
                f.f21,
                f.n12,
            ]
        };
        let a = vals(&st, e);
        let b = vals(&st2, e);
        let scales = &ctx.scales;
        // odd columns change sign in the mirror
        let odd = [
            true, true, true, true, true, true, true, false, true, false, true, false,
        ];
        let mut out = vec![Estimate {
            value: tf.clone(),
            err: Float::with_val(p, tf.abs_ref()) >> (p as i32 - 2),
            exact_zero: t.is_zero(),
            scale: std::sync::Arc::new(ctx.ts.clone()),
            exact_text: None,
            diff_weight: 1,
        }];
        for i in 0..12 {
            let prop = Float::with_val(p, &b[i] - &a[i]).abs();
            let ulps = Float::with_val(p, a[i].abs_ref()) >> (p as i32 - 4);
            let zero = (i == 8 && floor == Floor::Slip) || (i == 10 && contact == Contact::Slip);
            let v = if odd[i] {
                self.odd(a[i].clone())
            } else {
                a[i].clone()
            };
            out.push(Estimate {
                value: v,
                err: prop + ulps,
                exact_zero: zero,
                scale: std::sync::Arc::new(scales[i].clone()),
                exact_text: None,
                diff_weight: 1,
            });
        }
        Ok(out)
    }
}

/// Which of the 21 columns of a motion row (`crate::motion::point::COLUMNS`)
/// change sign in the mirror image: all but t, y2, ẏ2, N1, N12 and the work.
const ODD: [bool; 21] = [
    false, true, true, true, true, true, true, true, false, true, true, true, false, true, true,
    false, true, false, true, true, false,
];

impl Route {
    /// Every column of a motion row (t, θ, θ̇, θ̈, φ1, φ2, x1, x2, y2, ẋ1,
    /// φ̇1, ẋ2, ẏ2, φ̇2, F1, N1, F21, N12, s1, s12, work) at δ = θ − θ0
    /// reached at time `t`, in the user's frame (mirrored back), at `p`
    /// bits; and the total energy. φ2 is 0 at t = 0; the slip speed of a
    /// rolling or held contact is exactly 0, as is the work.
    ///
    /// Errors: none beyond building the engine at `p`.
    pub fn columns_at(&mut self, delta: &Float, t: &Float, p: u32) -> Result<(Vec<Float>, Float)> {
        let sign = self.sign;
        let e = self.engine(p)?;
        Ok(columns_of(&e.dynm, sign, delta, t))
    }
}

/// [`Route::columns_at`] by the dynamics `dy` (at its precision), `sign`
/// the route's mirror.
fn columns_of(dy: &Dyn, sign: i32, delta: &Float, t: &Float) -> (Vec<Float>, Float) {
    let p = dy.prec;
    let (floor, contact) = (dy.floor, dy.contact);
    {
        // r, r1, r2 at p bits as the dynamics holds them (each the
        // correctly rounded exact parameter)
        let (r, r1, r2) = (&dy.r, &dy.r1, &dy.r2);
        let st = dy.state(delta);
        let pos = dy.positions_phi2(&st, t);
        let f = dy.forces(&st);
        // T + V with V = m2 g (y2 − r1) = m2 g r cos θ: heights above
        // cylinder 1's centre, System::energy's zero of the potential
        let energy = dy.energy(&st);
        let [xd, pd, sd] = &st.v;
        let td = &st.thetadot;
        let x2 = Float::with_val(p, r * &st.s) + &pos[0];
        let y2 = Float::with_val(p, r * &st.c) + r1;
        let x2d = Float::with_val(p, r * &st.c) * td + xd;
        let y2d = -(Float::with_val(p, r * &st.s) * td);
        let s1 = if floor == Floor::Slip {
            Float::with_val(p, xd - Float::with_val(p, r1 * pd))
        } else {
            Float::new(p)
        };
        let s12 = if contact == Contact::Slip {
            Float::with_val(p, r * td) + Float::with_val(p, r2 * sd) - Float::with_val(p, r1 * pd)
        } else {
            Float::new(p)
        };
        let phi2_dot = Float::with_val(p, sd + td);
        // the state's own values moved into the columns
        let [x1, phi1, phi2] = pos;
        let [xd, pd, _] = st.v;
        let vals = vec![
            Float::with_val(p, t),
            st.theta,
            st.thetadot,
            st.thetaddot,
            phi1,
            phi2,
            x1,
            x2,
            y2,
            xd,
            pd,
            x2d,
            y2d,
            phi2_dot,
            f.f1,
            f.n1,
            f.f21,
            f.n12,
            s1,
            s12,
            Float::new(p),
        ];
        let out = vals
            .into_iter()
            .zip(ODD)
            .map(|(v, odd)| if odd && sign < 0 { -v } else { v })
            .collect();
        (out, energy)
    }
}

impl Route {
    /// The error of each column `a` of [`Route::columns_at`] at δ = `delta`
    /// and time `t` (p bits), where the ladder's lower run found `delta_low`
    /// and the route bounds δ's own error by `derr`: δ is then known to
    /// within b = |δ − δ_low| + derr. Each column's error is twice what b
    /// carries into it to first order, |G′(δ)|·b, and four times the running
    /// bound on the formulas' roundings at p bits (at least 16 units of the
    /// value's last place), from the same formulas evaluated in binary64
    /// with their derivative ([`crate::mechanics::dynamics::shadow`]), whose
    /// values must be `a`'s to binary64's accuracy. Where they are not (a
    /// value or a constant outside binary64's range), the error is measured
    /// instead: the columns at δ_low, 32 bits more and the time `t_hi` (the
    /// time more precise than `t` where `t` was rounded to p bits for these
    /// columns: its rounding measured too; else `t` itself) — the roundings
    /// and δ's difference at once, counted twice — and at δ + derr. The t and θ
    /// entries are left 0 (the caller's), as is the work (0 by the laws).
    ///
    /// Errors: none beyond building the engine at `p`.
    #[allow(clippy::too_many_arguments)]
    pub fn column_errors(
        &mut self,
        a: &[Float],
        delta: &Float,
        delta_low: &Float,
        derr: &Float,
        t: &Float,
        t_hi: &Float,
        p: u32,
    ) -> Result<Vec<Float>> {
        let b = Float::with_val(p, delta - delta_low).abs() + derr;
        let e = self.engine(p)?;
        if let Some(err) = shadow_errors(&e.dynm, a, delta, &b, t) {
            return Ok(err);
        }
        let sign = self.sign;
        let ulps = |x: &Float| Float::with_val(p, x.abs_ref()) >> (p as i32 - 4);
        if !self.caches.dyn_above.contains_key(&p) {
            let hi = Dyn::new(&self.work, &self.red, p + 32)?;
            self.caches.dyn_above.insert(p, hi);
        }
        let hi = &self.caches.dyn_above[&p];
        let (lo, _) = columns_of(hi, sign, &Float::with_val(p + 32, delta_low), t_hi);
        let (up, _) = self.columns_at(&Float::with_val(p, delta + derr), t, p)?;
        let mut err: Vec<Float> = a
            .iter()
            .zip(lo.iter().zip(&up))
            .map(|(x, (l, u))| {
                Float::with_val(p, x - l).abs() * 2u32 + Float::with_val(p, x - u).abs() + ulps(x)
            })
            .collect();
        err[0] = Float::new(p);
        err[1] = Float::new(p);
        Ok(err)
    }
}

/// The errors of [`Route::column_errors`] from the binary64 shadow of the
/// formulas, `None` where it does not hold them.
fn shadow_errors(dy: &Dyn, a: &[Float], delta: &Float, b: &Float, t: &Float) -> Option<Vec<Float>> {
    use crate::mechanics::dynamics::shadow;
    let p = dy.prec;
    // δ exact (b = 0, the start): no derivative is needed, nor infinite;
    // the time's conversion to p bits is counted as a rounding
    let seed = if b.is_zero() { 0.0 } else { 1.0 };
    use crate::numeric::to_f64_near;
    let sh = shadow::columns(dy, to_f64_near(delta), seed, to_f64_near(t), true);
    // b = bm·2^be; the rounding unit 2^−p
    let (bm, be) = if b.is_zero() {
        (0.0, -(p as i32))
    } else {
        b.to_f64_exp()
    };
    let top = be.max(-(p as i32));
    let mut out = Vec::with_capacity(crate::motion::COLUMNS.len());
    out.extend([Float::new(p), Float::new(p)]);
    // a number binary64 holds well: 0, or within 2^±930 (10^±280)
    let held = |x: &Float| x.is_zero() || x.get_exp().is_some_and(|e| e.abs() <= 930);
    // (b enters by its binary exponent, whatever it is)
    if !held(delta) || !held(t) {
        return None;
    }
    for (s, x) in sh.iter().zip(&a[2..20]) {
        // the shadow holds the formulas: finite, within binary64's normal
        // range, and the value p bits computed, to binary64's accuracy
        let xv = to_f64_near(x).abs();
        if !s.is_finite()
            || !held(x)
            || !(s.v == 0.0 || (1e-280..=1e280).contains(&s.v.abs()))
            || (s.v.abs() - xv).abs() > 8.0 * s.e * f64::EPSILON
        {
            return None;
        }
        let prop = 2.0 * s.d_bound() * bm;
        let round = 4.0 * s.e + 16.0 * s.v.abs();
        let y = prop * 2f64.powi(be - top) + round * 2f64.powi(-(p as i32) - top);
        if !y.is_finite() {
            return None;
        }
        // the f64 sum rounded up by far more than its own roundings
        let mut o = Float::with_val(p, y * (1.0 + 1e-12));
        o <<= top;
        out.push(o);
    }
    out.push(Float::new(p));
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::Exact;
    use crate::mechanics::dynamics::shadow::columns;
    use crate::mechanics::Reduced;
    use crate::model::{Ideal, Params, Start, VARIANTS};
    use rug::Rational;

    fn dyn_at(contact: Contact, floor: Floor, thetadot0: Rational, p: u32) -> Dyn {
        let params = Params::identical_solid();
        let start = Start {
            theta0: Exact::rational(Rational::from((1, 10))),
            thetadot0,
            // a common rolling where the floor lets cylinder 1 move
            omega0: if floor == Floor::Fixed {
                Rational::new()
            } else {
                Rational::from((1, 7))
            },
        };
        let m = Ideal::new(params, floor, contact, start).unwrap();
        let red = Reduced::new(&m).unwrap();
        Dyn::new(&m, &red, p).unwrap()
    }

    /// The columns θ̇ … s12 as the energy route computes them at `dy`'s
    /// precision (the order of [`columns`]).
    fn exact_columns(dy: &Dyn, delta: &Float, t: &Float) -> Vec<Float> {
        columns_of(dy, 1, delta, t).0[2..20].to_vec()
    }

    /// The binary64 shadow of the formulas ([`columns`]) holds the route's:
    /// its derivative is the closed forms' (a central difference at 400
    /// bits), and its rounding bound covers the error of the p-bit values
    /// against the same formulas at 400 bits, for every contact law of a
    /// conservative phase, from rest and from a moving start, at small and
    /// large δ — near the separation, where N12 is a cancellation.
    #[test]
    fn derivative_and_rounding_bound_hold() {
        let hi = 400;
        for (floor, contact) in VARIANTS {
            for td0 in [
                Rational::new(),
                Rational::from((1, 3)),
                Rational::from((2, 5)),
            ] {
                for p in [60u32, 124, 200] {
                    let lo = dyn_at(contact, floor, td0.clone(), p);
                    let dh = dyn_at(contact, floor, td0.clone(), hi);
                    for (dv, tv) in [(1e-9, 1e-4), (0.013, 0.3), (0.4, 2.0), (0.72, 3.1)] {
                        let d = Float::with_val(p, dv);
                        let t = Float::with_val(p, tv);
                        let sh = columns(&lo, d.to_f64(), 1.0, t.to_f64(), false);
                        let a = exact_columns(&lo, &d, &t);
                        let b =
                            exact_columns(&dh, &Float::with_val(hi, &d), &Float::with_val(hi, &t));
                        let eps = Float::with_val(hi, 1e-40);
                        let dp = Float::with_val(hi, &d + &eps);
                        let dm = Float::with_val(hi, &d - &eps);
                        let bp = exact_columns(&dh, &dp, &Float::with_val(hi, &t));
                        let bm = exact_columns(&dh, &dm, &Float::with_val(hi, &t));
                        for k in 0..18 {
                            if !b[k].is_finite() {
                                continue; // a negative θ̇² beyond the turn
                            }
                            let err = Float::with_val(hi, &a[k] - &b[k]).abs().to_f64();
                            let bound = sh[k].e * 2f64.powi(-(p as i32));
                            assert!(
                                err <= bound,
                                "{contact:?}/{floor:?} td0 {td0} p {p} δ {dv} col {k}: error {err:e} > bound {bound:e}"
                            );
                            let fd = Float::with_val(hi, &bp[k] - &bm[k]).to_f64() / 2e-40;
                            // within binary64's error bound on it (2^−45 of
                            // its terms' size: a cancelling derivative is
                            // known only to that)
                            let tol = sh[k].m * 2f64.powi(-45) + 1e-300;
                            assert!(
                                (sh[k].d - fd).abs() <= tol,
                                "{contact:?}/{floor:?} td0 {td0} δ {dv} col {k}: derivative {} against {fd}",
                                sh[k].d
                            );
                        }
                    }
                }
            }
        }
    }

    /// The binary64 shadow answers at every precision (δ's bound far below
    /// binary64's range, 2^−p at thousands of bits, is taken by its
    /// exponent), and its errors cover the p-bit columns' against 200 bits
    /// more, with δ exact.
    #[test]
    fn the_shadow_answers_at_any_precision_and_covers_the_roundings() {
        for p in [124u32, 1100, 3400] {
            for (floor, contact) in VARIANTS {
                let lo = dyn_at(contact, floor, Rational::from((1, 3)), p);
                let hi = dyn_at(contact, floor, Rational::from((1, 3)), p + 200);
                let d = Float::with_val(p, 0.3);
                let t = Float::with_val(p, 1.7);
                let (a, _) = columns_of(&lo, 1, &d, &t);
                let (b, _) = columns_of(
                    &hi,
                    1,
                    &Float::with_val(p + 200, &d),
                    &Float::with_val(p + 200, &t),
                );
                let bound = Float::with_val(p, &d) >> p;
                let err = shadow_errors(&lo, &a, &d, &bound, &t)
                    .unwrap_or_else(|| panic!("{floor:?}/{contact:?} at {p} bits: no shadow"));
                for k in 2..20 {
                    let diff = Float::with_val(p + 200, &a[k] - &b[k]).abs();
                    assert!(
                        diff <= err[k],
                        "{floor:?}/{contact:?} at {p} bits, column {k}"
                    );
                }
            }
        }
    }
}
