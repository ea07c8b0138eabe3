//! The KKT solve: the mass matrix M(q) and the generalised forces
//! h(q, q̇) of the stack, the KKT matrix with the rows and the sliding
//! friction assembled into the workspace, and its solution for q̈ and the
//! multipliers by Gaussian elimination with partial pivoting (one or several
//! right-hand sides at once).

use super::{psi, rr, th, Accel, System, PHI1, X1, Y1};
use crate::error::{Error, Result};
use rug::ops::NegAssign;
use rug::{Assign, Float};

/// The same number, zero's sign included (NaN is never the same).
fn same(a: &Float, b: &Float) -> bool {
    a == b && a.is_sign_negative() == b.is_sign_negative()
}

impl System {
    /// sin θ_j and cos θ_j into the workspace, each computed once per angle
    /// (the same bits as computing it again).
    fn trig(&mut self, q: &[Float]) {
        for j in 0..self.n - 1 {
            let ws = &mut self.ws;
            ws.t.assign(&q[th(j)]);
            if same(&ws.t, &ws.trig_at[j]) {
                continue;
            }
            ws.trig_at[j].assign(&ws.t);
            // an angle no motion reaches (|θ| ≥ 2^16 rad: an explicit
            // integrator's trial substeps diverging over a stiff interval)
            // gets NaN, not MPFR's reduction by π at as many bits as the
            // angle's exponent (10^8 bits, hours): the step's error estimate
            // is then NaN and the step is rejected for a shorter one
            if ws.t.get_exp().is_some_and(|e| e > 16) {
                ws.s[j].assign(f64::NAN);
                ws.c[j].assign(f64::NAN);
                continue;
            }
            // MPFR's bits, in fixed point where it can (t, s, c share the
            // precision)
            crate::numeric::trig::sin_cos_into(&ws.t, &mut ws.s[j], &mut ws.c[j]);
        }
    }

    /// θ_j, sin θ_j and cos θ_j of every line (in turn) when the workspace
    /// holds the sine and cosine for exactly q's angles, else empty: for a
    /// [`crate::integrate::solve::Sample`] to carry to [`System::prime_trig`].
    pub fn trig_kept(&self, q: &[Float]) -> Vec<Float> {
        let ws = &self.ws;
        let mut out = Vec::with_capacity(3 * ws.s.len());
        for j in 0..self.n - 1 {
            let th = &q[th(j)];
            if th.prec() != self.prec || !same(th, &ws.trig_at[j]) {
                return Vec::new();
            }
            out.push(th.clone());
            out.push(ws.s[j].clone());
            out.push(ws.c[j].clone());
        }
        out
    }

    /// Puts back the sines and cosines that [`System::trig_kept`] gave, where
    /// q's angles are the very ones they were kept for at this precision
    /// (else nothing): the same bits the workspace would compute there.
    pub fn prime_trig(&mut self, q: &[Float], kept: &[Float]) {
        let n = self.n - 1;
        let fits = kept.len() == 3 * n
            && kept.iter().all(|x| x.prec() == self.prec)
            && (0..n).all(|j| {
                let th = &q[th(j)];
                th.prec() == self.prec && same(th, &kept[3 * j])
            });
        if !fits {
            return;
        }
        let ws = &mut self.ws;
        for j in 0..n {
            ws.trig_at[j].assign(&kept[3 * j]);
            ws.s[j].assign(&kept[3 * j + 1]);
            ws.c[j].assign(&kept[3 * j + 2]);
        }
    }

    /// sin θ and cos θ of the first line when the workspace holds them for
    /// exactly `theta` at this precision (after a KKT solve or an energy at
    /// the same angle), else `None`.
    pub fn cached_trig(&self, theta: &Float) -> Option<(&Float, &Float)> {
        let at = self.ws.trig_at.first()?;
        (theta.prec() == self.prec && same(theta, at)).then(|| (&self.ws.s[0], &self.ws.c[0]))
    }

    /// Fills the workspace mass matrix at q (computes the trigonometry);
    /// kept where it already is the matrix at q's angles and lengths (the
    /// only coordinates it depends on: the same bits as building it again).
    pub(super) fn mass_matrix(&mut self, q: &[Float]) {
        self.trig(q);
        let nq = self.nq();
        let nl = self.n - 1;
        let ws = &mut self.ws;
        let at = |j: usize| if j % 2 == 0 { th(j / 2) } else { rr(j / 2) };
        if (0..2 * nl).all(|j| same(&q[at(j)], &ws.m_at[j])) {
            return;
        }
        for (j, m) in ws.m_at.iter_mut().enumerate() {
            m.set_prec(q[at(j)].prec());
            m.assign(&q[at(j)]);
        }
        for x in ws.m.iter_mut() {
            x.assign(0u32);
        }
        let mm = &mut ws.m;
        let idx = |i: usize, j: usize| i * nq + j;
        mm[idx(X1, X1)].assign(&self.mtot);
        mm[idx(Y1, Y1)].assign(&self.mtot);
        mm[idx(PHI1, PHI1)].assign(&self.inertia[0]);
        for j in 0..nl {
            mm[idx(psi(j), psi(j))].assign(&self.inertia[j + 1]);
        }
        let t = &mut ws.t;
        let t2 = &mut ws.t2;
        for j in 0..nl {
            let (a, b) = (th(j), rr(j));
            let s = &ws.s[j];
            let c = &ws.c[j];
            let sa = &self.above[j];
            let rj = &q[b];
            // x1–θ_j, x1–r_j, y1–θ_j, y1–r_j
            t.assign(sa * rj);
            mm[idx(X1, a)].assign(&*t * c);
            mm[idx(Y1, a)].assign(&*t * s);
            mm[idx(Y1, a)].neg_assign();
            mm[idx(X1, b)].assign(sa * s);
            mm[idx(Y1, b)].assign(sa * c);
            for k in 0..=j {
                // pairs (j, k), k ≤ j: bodies above line j move with both
                let (ak, bk) = (th(k), rr(k));
                let sk = &ws.s[k];
                let ck = &ws.c[k];
                let rk = &q[bk];
                // cos(θj − θk), sin(θk − θj)
                let mut cjk = Float::with_val(self.prec, c * ck);
                cjk += s * sk;
                let mut skj = Float::with_val(self.prec, sk * c);
                skj -= ck * s;
                t.assign(sa * &cjk);
                // r_j–r_k
                mm[idx(b, bk)].assign(&*t);
                // θ_j–θ_k
                t2.assign(&*t * rj);
                mm[idx(a, ak)].assign(&*t2 * rk);
                if k < j {
                    // θ_j–r_k: S r_j sin(θ_k − θ_j); θ_k–r_j: S r_k sin(θ_j − θ_k)
                    t.assign(sa * &skj);
                    mm[idx(a, bk)].assign(&*t * rj);
                    mm[idx(ak, b)].assign(&*t * rk);
                    mm[idx(ak, b)].neg_assign();
                }
            }
        }
        // symmetrise: each pair was written on one side only
        for i in 0..nq {
            for j in 0..i {
                let (lo, hi) = mm.split_at_mut(i * nq);
                let upper = &mut lo[j * nq + i];
                let lower = &mut hi[j];
                if lower.is_zero() {
                    lower.assign(&*upper);
                } else {
                    upper.assign(&*lower);
                }
            }
        }
    }

    /// Generalised forces h(q, q̇) (gravity and velocity terms), into the
    /// workspace; the trigonometry must be current (call after `mass_matrix`).
    fn forces_h(&mut self, q: &[Float], v: &[Float]) {
        let p = self.prec;
        let nl = self.n - 1;
        let ws = &mut self.ws;
        for x in ws.h.iter_mut() {
            x.assign(0u32);
        }
        let h = &mut ws.h;
        h[Y1].assign(&self.mtot * &self.g);
        h[Y1].neg_assign();
        // per-line centripetal/Coriolis accelerations of the relative vector
        let mut cx = vec![Float::new(p); nl];
        let mut cy = vec![Float::new(p); nl];
        for j in 0..nl {
            let s = &ws.s[j];
            let c = &ws.c[j];
            let rj = &q[rr(j)];
            let td = &v[th(j)];
            let rd = &v[rr(j)];
            let td2 = Float::with_val(p, td.square_ref());
            let rtd2 = Float::with_val(p, rj * &td2);
            let two_rd_td = Float::with_val(p, rd * td) * 2u32;
            // c^x = −r s θ̇² + 2 ṙ c θ̇ ; c^y = −r c θ̇² − 2 ṙ s θ̇
            cx[j].assign(&two_rd_td * c);
            cx[j] -= &rtd2 * s;
            cy[j].assign(&two_rd_td * s);
            cy[j] += &rtd2 * c;
            cy[j].neg_assign();
            // gravity on θ_j, r_j
            let sg = Float::with_val(p, &self.above[j] * &self.g);
            h[th(j)].assign(&sg * rj);
            h[th(j)] *= s;
            h[rr(j)].assign(&sg * c);
            h[rr(j)].neg_assign();
        }
        // body i ≥ 1 accelerates by Σ_{j<i} c_j (velocity part)
        let mut ax = Float::new(p);
        let mut ay = Float::new(p);
        // X_j = Σ_{i>j} m_i acx_i, accumulated from the top down
        let mut acx = vec![Float::new(p); self.n];
        let mut acy = vec![Float::new(p); self.n];
        for i in 1..self.n {
            ax += &cx[i - 1];
            ay += &cy[i - 1];
            acx[i].assign(&ax * &self.m[i]);
            acy[i].assign(&ay * &self.m[i]);
        }
        let mut sx = Float::new(p);
        let mut sy = Float::new(p);
        for j in (0..nl).rev() {
            sx += &acx[j + 1];
            sy += &acy[j + 1];
            let s = &ws.s[j];
            let c = &ws.c[j];
            let rj = &q[rr(j)];
            // h_θj −= r_j (c X − s Y); h_rj −= s X + c Y
            let mut t = Float::with_val(p, c * &sx);
            t -= s * &sy;
            t *= rj;
            h[th(j)] -= &t;
            let mut u = Float::with_val(p, s * &sx);
            u += c * &sy;
            h[rr(j)] -= &u;
        }
        h[X1] -= &sx;
        h[Y1] -= &sy;
    }

    /// Solves the KKT system at (q, q̇): the accelerations and the
    /// multipliers (one per row of [`System::rows`]).
    ///
    /// Errors: a singular system (not expected for a valid model).
    pub fn accel(&mut self, q: &[Float], v: &[Float]) -> Result<Accel> {
        let mut qdd = vec![Float::new(self.prec); self.nq()];
        let mut lambda = vec![Float::new(self.prec); self.rows.len()];
        self.accel_into(q, v, &mut qdd, Some(&mut lambda))?;
        Ok(Accel { qdd, lambda })
    }

    /// The accelerations and multipliers at q for θ̇_j = 0 and θ̇_j = 2^k
    /// (every other rate 0), from one elimination with two right-hand
    /// sides. With ṙ = 0 the equations depend on the rates only through the
    /// θ̇_j², so q̈ = a + b θ̇_j² with a the first and a + b 4^k the second.
    /// 2^k should be near the motion's natural rate sqrt(g/r): there the
    /// two terms are of one size and b = (second − a)/4^k loses nothing to
    /// cancellation (at θ̇ = 1 with g/r = 10^20, b would be the difference of
    /// two numbers 10^20 times larger than itself).
    ///
    /// Errors: a singular system.
    pub fn accel_pair(&mut self, q: &[Float], j: usize, k: i32) -> Result<(Accel, Accel)> {
        let nq = self.nq();
        let nk = nq + self.rows.len();
        let p = self.prec;
        let mut v = vec![Float::new(p); nq];
        self.assemble(q, &v);
        // the second right-hand side: the rates enter h only (the rows'
        // right-hand sides carry −ṙ θ̇, which is 0 for both)
        v[th(j)].assign(1u32);
        v[th(j)] <<= k;
        self.forces_h(q, &v);
        let mut b1 = self.ws.b[..nk].to_vec();
        for (x, h) in b1.iter_mut().zip(&self.ws.h[..nq]) {
            x.assign(h);
        }
        let mut b0 = std::mem::take(&mut self.ws.b);
        let mut x0 = vec![Float::new(p); nk];
        let mut x1 = vec![Float::new(p); nk];
        let ok = gauss_many(
            &mut self.ws.a,
            &mut [&mut b0, &mut b1],
            &mut [&mut x0, &mut x1],
            nk,
        );
        self.ws.b = b0;
        ok.ok_or_else(|| Error::not_physical("the constraint (KKT) system is singular"))?;
        let mut out = [x0, x1].into_iter().map(|mut x| {
            let lambda = x.split_off(nq);
            Accel { qdd: x, lambda }
        });
        let a0 = out.next().expect("two solutions");
        let a1 = out.next().expect("two solutions");
        Ok((a0, a1))
    }

    /// [`System::accel`] into caller buffers (the multipliers only if asked).
    pub fn accel_into(
        &mut self,
        q: &[Float],
        v: &[Float],
        qdd: &mut [Float],
        lambda: Option<&mut Vec<Float>>,
    ) -> Result<()> {
        let nq = self.nq();
        let nk = nq + self.rows.len();
        self.assemble(q, v);
        let ws = &mut self.ws;
        gauss(&mut ws.a, &mut ws.b, &mut ws.x, nk)
            .ok_or_else(|| Error::not_physical("the constraint (KKT) system is singular"))?;
        for (o, x) in qdd.iter_mut().zip(&ws.x[..nq]) {
            o.assign(x);
        }
        if let Some(l) = lambda {
            for (o, x) in l.iter_mut().zip(&ws.x[nq..]) {
                o.assign(x);
            }
        }
        Ok(())
    }

    /// The KKT matrix and right-hand side at (q, q̇) into the workspace.
    fn assemble(&mut self, q: &[Float], v: &[Float]) {
        let nq = self.nq();
        self.mass_matrix(q);
        self.forces_h(q, v);
        let nr = self.rows.len();
        let nk = nq + nr;
        let rows: Vec<(Vec<(usize, Float)>, Float)> = self
            .rows
            .iter()
            .map(|&r| self.row_coeffs(r, q, v))
            .collect();
        let ws = &mut self.ws;
        for x in ws.a.iter_mut() {
            x.assign(0u32);
        }
        for i in 0..nq {
            for j in 0..nq {
                let mij = &ws.m[i * nq + j];
                if !mij.is_zero() {
                    ws.a[i * nk + j].assign(mij);
                }
            }
            ws.b[i].assign(&ws.h[i]);
        }
        for (k, (coefs, rhs)) in rows.iter().enumerate() {
            for (i, c) in coefs {
                ws.a[(nq + k) * nk + i].assign(c);
                ws.a[i * nk + nq + k].assign(c);
                ws.a[i * nk + nq + k].neg_assign();
            }
            ws.b[nq + k].assign(rhs);
        }
        // sliding friction −μk σ N along the slip direction: M q̈ − J_nᵀ N
        // + μk σ J_tᵀ N = h, so the normal row's column gains μk σ J_t
        for sl in &self.slips {
            let col = nq + sl.normal;
            for (i, c) in Self::tangent_of(&self.rho, sl.at, q) {
                ws.a[i * nk + col] += Float::with_val(self.prec, &c * &sl.mu_sigma);
            }
        }
    }
}

/// The solution of a row-major n×n system for several right-hand sides at
/// once; the solution of `bs[k]` goes to `xs[k]`. `None` if singular.
///
/// A constraint (KKT) system has rows and columns with a single nonzero
/// entry: a holonomic constraint on one coordinate (y1 = r1, the
/// separation r of touching cylinders) fixes that coordinate's
/// acceleration, and a multiplier acting on one coordinate only is read
/// from that coordinate's equation once the others are known. They are
/// taken out first (exactly: one division, and the substitution into the
/// other rows); the rest — at most a 6×6 for two rolling cylinders instead
/// of 10×10 — goes to Gaussian elimination with partial pivoting
/// ([`gauss_dense`]). `a` and the right-hand sides are left in an
/// unspecified state.
pub(crate) fn gauss_many(
    a: &mut [Float],
    bs: &mut [&mut [Float]],
    xs: &mut [&mut [Float]],
    n: usize,
) -> Option<()> {
    let mut row_on = vec![true; n];
    let mut col_on = vec![true; n];
    // singleton columns, in the order found: (row, column, the columns
    // still in the system then)
    let mut later: Vec<(usize, usize, Vec<bool>)> = Vec::new();
    // the one index of `it`: None if there is none (the system is
    // singular), Some(None) if there are several
    let single = |it: &mut dyn Iterator<Item = usize>| -> Option<Option<usize>> {
        let first = it.next()?;
        Some(it.next().is_none().then_some(first))
    };
    loop {
        let mut found = false;
        for r in 0..n {
            if !row_on[r] {
                continue;
            }
            let Some(c) = single(&mut (0..n).filter(|&c| col_on[c] && !a[r * n + c].is_zero()))?
            else {
                continue;
            };
            // x_c from row r; substituted into the other rows
            for (b, x) in bs.iter_mut().zip(xs.iter_mut()) {
                x[c].assign(&b[r] / &a[r * n + c]);
                for i in 0..n {
                    if i != r && row_on[i] && !a[i * n + c].is_zero() {
                        b[i] -= &a[i * n + c] * &x[c];
                    }
                }
            }
            row_on[r] = false;
            col_on[c] = false;
            found = true;
        }
        for c in 0..n {
            if !col_on[c] {
                continue;
            }
            if let Some(r) = single(&mut (0..n).filter(|&r| row_on[r] && !a[r * n + c].is_zero()))?
            {
                later.push((r, c, col_on.clone()));
                row_on[r] = false;
                col_on[c] = false;
                found = true;
            }
        }
        if !found {
            break;
        }
    }
    let mut rows: Vec<usize> = (0..n).filter(|&r| row_on[r]).collect();
    let cols: Vec<usize> = (0..n).filter(|&c| col_on[c]).collect();
    if rows.len() != cols.len() {
        return None;
    }
    if !rows.is_empty() {
        gauss_dense(a, n, &mut rows, &cols, bs, xs)?;
    }
    // the singleton columns, last found first: every other unknown of their
    // row is known by then (those fixed before are in the right-hand side;
    // the row's right-hand sides are as they were when it was taken out:
    // only rows still in the system change after that)
    for (r, c, on) in later.into_iter().rev() {
        for (b, x) in bs.iter().zip(xs.iter_mut()) {
            let mut s = b[r].clone();
            for j in 0..n {
                if j != c && on[j] && !a[r * n + j].is_zero() {
                    s -= &a[r * n + j] * &x[j];
                }
            }
            x[c].assign(&s / &a[r * n + c]);
        }
    }
    Some(())
}

/// Gaussian elimination with partial pivoting on the m×m system of rows
/// `rows` and columns `cols` (m each) of the row-major n×n matrix `a`, in
/// place (a pivot swaps two entries of `rows`, not the rows), for several
/// right-hand sides at once (one elimination, read at `rows`); the solution
/// of `bs[k]` goes to `xs[k]` at `cols`. `None` if singular.
fn gauss_dense(
    a: &mut [Float],
    n: usize,
    rows: &mut [usize],
    cols: &[usize],
    bs: &mut [&mut [Float]],
    xs: &mut [&mut [Float]],
) -> Option<()> {
    let m = rows.len();
    let p = bs
        .first()
        .and_then(|b| b.first())
        .map(|f| f.prec())
        .unwrap_or(64);
    let mut f = Float::new(p);
    // each pivot's reciprocal, for the eliminations below it and the back
    // substitution of every right-hand side: one division per column (a
    // division costs several multiplications at a few limbs)
    let mut inv = vec![Float::new(p); m];
    for col in 0..m {
        let cc = cols[col];
        let mut piv = col;
        for i in col + 1..m {
            if a[rows[i] * n + cc].cmp_abs(&a[rows[piv] * n + cc])
                == Some(std::cmp::Ordering::Greater)
            {
                piv = i;
            }
        }
        if a[rows[piv] * n + cc].is_zero() {
            return None;
        }
        rows.swap(piv, col);
        let pr = rows[col];
        inv[col].assign(a[pr * n + cc].recip_ref());
        for &ri in &rows[col + 1..] {
            if a[ri * n + cc].is_zero() {
                continue;
            }
            f.assign(&a[ri * n + cc] * &inv[col]);
            for &cj in &cols[col + 1..] {
                // the pivot row and this one are distinct rows of `a`
                let (pv, rv) = if pr < ri {
                    let (lo, hi) = a.split_at_mut(ri * n);
                    (&lo[pr * n + cj], &mut hi[cj])
                } else {
                    let (lo, hi) = a.split_at_mut(pr * n);
                    (&hi[cj], &mut lo[ri * n + cj])
                };
                if !pv.is_zero() {
                    *rv -= &f * pv;
                }
            }
            a[ri * n + cc].assign(0u32);
            for b in bs.iter_mut() {
                let (bp, bi) = if pr < ri {
                    let (lo, hi) = b.split_at_mut(ri);
                    (&lo[pr], &mut hi[0])
                } else {
                    let (lo, hi) = b.split_at_mut(pr);
                    (&hi[0], &mut lo[ri])
                };
                *bi -= &f * bp;
            }
        }
    }
    for (b, x) in bs.iter().zip(xs.iter_mut()) {
        for i in (0..m).rev() {
            let ri = rows[i];
            let mut s = b[ri].clone();
            for j in i + 1..m {
                let v = &a[ri * n + cols[j]];
                if !v.is_zero() {
                    s -= v * &x[cols[j]];
                }
            }
            x[cols[i]].assign(&s * &inv[i]);
        }
    }
    Some(())
}

/// [`gauss_many`] for one right-hand side.
pub(crate) fn gauss(a: &mut [Float], b: &mut [Float], x: &mut [Float], n: usize) -> Option<()> {
    gauss_many(a, &mut [b], &mut [x], n)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The workspace's kept trigonometry and mass matrix are the bits a
    /// fresh system computes: an energy after a solve at another state (or
    /// at another centre distance alone), with the sample's sin and cos put
    /// back or not, equals a fresh system's; kept values are refused at
    /// another angle or precision, and used where they fit.
    #[test]
    fn kept_trigonometry_and_mass_matrix_are_the_fresh_bits() {
        use crate::exact::Exact;
        use crate::mechanics::system::StackModel;
        use crate::model::Ideal;
        let p = 150;
        let model = Ideal::paper_default(Exact::parse("theta0", "1/10", false).unwrap());
        let sm = StackModel::from_model(&model);
        let fresh = |p: u32| System::new(&sm, p).unwrap();
        let mut sys = fresh(p);
        let (q0, v0) = sys.initial_state(&sm).unwrap();
        // a second state: another angle and another centre distance
        let mut q1 = q0.clone();
        q1[th(0)] += 0.25f64;
        q1[rr(0)] += 1e-3f64;
        let mut v1 = v0.clone();
        v1[th(0)] += 0.5f64;
        // a third: the centre distance alone moved (the mass matrix's key)
        let mut q2 = q0.clone();
        q2[rr(0)] += 1e-3f64;
        sys.accel(&q0, &v0).unwrap();
        assert_eq!(sys.energy(&q2, &v1), fresh(p).energy(&q2, &v1));
        sys.accel(&q0, &v0).unwrap();
        let kept = sys.trig_kept(&q0);
        assert_eq!(kept.len(), 3);
        assert!(sys.trig_kept(&q1).is_empty());
        let e_fresh = fresh(p).energy(&q1, &v1);
        assert_eq!(sys.energy(&q1, &v1), e_fresh);
        // kept at q0, offered at q1: refused (the workspace keeps q1's)
        sys.prime_trig(&q1, &kept);
        let (s1, c1) = q1[th(0)].clone().sin_cos(Float::new(p));
        assert_eq!(sys.cached_trig(&q1[th(0)]), Some((&s1, &c1)));
        assert_eq!(sys.energy(&q1, &v1), e_fresh);
        // back at q0 through the kept values, after the workspace moved on
        sys.prime_trig(&q0, &kept);
        assert_eq!(sys.cached_trig(&q0[th(0)]), Some((&kept[1], &kept[2])));
        assert_eq!(sys.energy(&q0, &v0), fresh(p).energy(&q0, &v0));
        // kept at p, offered to a system at p + 64 at the same angle: refused
        let hi =
            |q: &[Float]| -> Vec<Float> { q.iter().map(|x| Float::with_val(p + 64, x)).collect() };
        let mut other = fresh(p + 64);
        other.accel(&hi(&q1), &hi(&v1)).unwrap();
        other.prime_trig(&hi(&q0), &kept);
        assert!(other.cached_trig(&hi(&q0)[th(0)]).is_none());
        // where they fit they are used as given: a wrong sine or cosine
        // would show (in the kinetic energy at v1, in the potential)
        for k in [1, 2] {
            let mut bad = kept.clone();
            bad[k] += 1e-30f64;
            sys.accel(&q1, &v1).unwrap();
            sys.prime_trig(&q0, &bad);
            assert_ne!(sys.energy(&q0, &v1), fresh(p).energy(&q0, &v1), "{k}");
        }
    }

    /// The reduced solve against plain elimination and against the
    /// residual, on a KKT-shaped system (a mass block, two singleton
    /// constraint rows, a rolling row, a multiplier column with an extra
    /// entry as sliding friction adds) and on a dense one, for two
    /// right-hand sides.
    #[test]
    fn reduced_solve_agrees_with_elimination() {
        let p = 200;
        let f = |x: f64| Float::with_val(p, x);
        // 4 coordinates, 3 constraints: n = 7
        let m = [
            [3.0, 0.2, 0.1, 0.0],
            [0.2, 2.5, 0.3, 0.4],
            [0.1, 0.3, 1.7, 0.0],
            [0.0, 0.4, 0.0, 1.1],
        ];
        // constraint rows: q1 alone, q3 alone, q0 − 0.7 q2
        let j: [[f64; 4]; 3] = [
            [0.0, 1.0, 0.0, 0.0],
            [0.0, 0.0, 0.0, 1.0],
            [1.0, 0.0, -0.7, 0.0],
        ];
        let n = 7;
        let mut kkt = vec![f(0.0); n * n];
        for i in 0..4 {
            for k in 0..4 {
                kkt[i * n + k] = f(m[i][k]);
            }
            for c in 0..3 {
                kkt[i * n + 4 + c] = f(-j[c][i]);
                kkt[(4 + c) * n + i] = f(j[c][i]);
            }
        }
        // sliding friction: the first multiplier's column gains an entry
        kkt[2 * n + 4] = f(0.3);
        let dense: Vec<Float> = (0..n * n)
            .map(|k| f(((k * 7 + 3) % 11) as f64 - 5.0 + if k % (n + 1) == 0 { 20.0 } else { 0.0 }))
            .collect();
        for a0 in [kkt, dense] {
            let b0: Vec<Float> = (0..n).map(|i| f(i as f64 * 0.37 - 1.0)).collect();
            let b1: Vec<Float> = (0..n).map(|i| f(1.0 / (i as f64 + 2.0))).collect();
            type Solver =
                fn(&mut [Float], &mut [&mut [Float]], &mut [&mut [Float]], usize) -> Option<()>;
            let solve = |g: Solver| {
                let (mut x0, mut x1) = (vec![f(0.0); n], vec![f(0.0); n]);
                let (mut c0, mut c1) = (b0.clone(), b1.clone());
                g(
                    &mut a0.clone(),
                    &mut [&mut c0, &mut c1],
                    &mut [&mut x0, &mut x1],
                    n,
                )
                .unwrap();
                (x0, x1)
            };
            let (x0, x1) = solve(gauss_many);
            // the dense elimination on the whole system, no singletons taken out
            let (y0, y1) = solve(|a, bs, xs, n| {
                let all: Vec<usize> = (0..n).collect();
                gauss_dense(a, n, &mut all.clone(), &all, bs, xs)
            });
            for (x, y, b) in [(&x0, &y0, &b0), (&x1, &y1, &b1)] {
                for i in 0..n {
                    let d = Float::with_val(p, &x[i] - &y[i]).abs().to_f64();
                    assert!(d < 1e-55, "x[{i}]: {d:e}");
                    // the residual of row i
                    let mut r = b[i].clone();
                    for k in 0..n {
                        r -= Float::with_val(p, &a0[i * n + k] * &x[k]);
                    }
                    assert!(r.abs().to_f64() < 1e-55, "row {i}");
                }
            }
        }
        // a singular system is refused
        let mut sing = vec![f(0.0); 4];
        sing[0] = f(1.0);
        sing[1] = f(2.0);
        let (mut b, mut x) = (vec![f(1.0), f(1.0)], vec![f(0.0), f(0.0)]);
        assert!(gauss_many(&mut sing, &mut [&mut b], &mut [&mut x], 2).is_none());
    }

    /// The workspace's sine and cosine, kept for the last angle, give the
    /// same bits as a fresh system: accelerations and energies at states
    /// visited in turn (the same angle again, another one, a negative zero)
    /// against a new system for each; and the kept values are offered only
    /// for exactly the angle they belong to.
    #[test]
    fn kept_trigonometry_is_the_fresh_one() {
        use crate::exact::Exact;
        use crate::mechanics::system::StackModel;
        use crate::model::Ideal;
        let p = 160;
        let model = Ideal::paper_default(Exact::parse("theta0", "1/10", false).unwrap());
        let sm = StackModel::from_model(&model);
        let mut kept = System::new(&sm, p).unwrap();
        let (q0, v0) = kept.initial_state(&sm).unwrap();
        let at = |theta: f64| {
            let mut q = q0.clone();
            q[th(0)] = Float::with_val(p, theta);
            q
        };
        let angles = [0.1, 0.1, 0.7, -0.0, 0.0, 0.7, 1.3];
        for &a in &angles {
            let q = at(a);
            let mut fresh = System::new(&sm, p).unwrap();
            let e_kept = kept.energy(&q, &v0);
            let e_fresh = fresh.energy(&q, &v0);
            assert_eq!(e_kept, e_fresh);
            let a_kept = kept.accel(&q, &v0).unwrap();
            let a_fresh = fresh.accel(&q, &v0).unwrap();
            for (x, y) in a_kept.qdd.iter().zip(&a_fresh.qdd) {
                assert!(
                    x == y && x.is_sign_negative() == y.is_sign_negative(),
                    "{a}: {x} {y}"
                );
            }
            let (s, c) = kept.cached_trig(&q[th(0)]).expect("kept for this angle");
            let (s2, c2) = Float::with_val(p, a).sin_cos(Float::new(p));
            assert!(*s == s2 && s.is_sign_negative() == s2.is_sign_negative() && *c == c2);
        }
        // another angle, another precision: not offered
        assert!(kept.cached_trig(&Float::with_val(p, 0.5)).is_none());
        assert!(kept.cached_trig(&Float::with_val(p + 1, 1.3)).is_none());
    }
}
