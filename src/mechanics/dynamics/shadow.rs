//! The error a conservative row's columns carry, at one working precision.
//!
//! Every column of a row of the energy route is a closed form of δ = θ − θ0
//! (and of the time, for the positions), evaluated by [`Dyn`] at p bits. Its
//! error has two parts: what δ's own error carries into it, G′(δ)·|Δδ|, and
//! the roundings of the formulas at p bits. This module evaluates the same
//! formulas, operation by operation in the same order, in binary64 on
//! [`Sh`] numbers that carry beside the value its derivative in δ (forward
//! mode) and a running bound on the roundings in units of 2^−p (each
//! operation adds |∂z/∂x|·e_x + |∂z/∂y|·e_y of its operands' and |z| of its
//! own; the standard running error analysis). A cancellation — N12 near the
//! separation, a velocity near zero — shows in that bound as it would in
//! the difference of two precisions, which it replaces for these columns.

use super::Dyn;
use crate::model::{Contact, Floor};
use rug::Float;

/// A value in binary64 with its derivative in δ, the size of the terms
/// that derivative sums (binary64's own error in it is a few units of 2^−53
/// of that size: a derivative that cancels is known only to it), and a
/// bound on the roundings it carries at p bits, in units of 2^−p.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sh {
    /// The value.
    pub v: f64,
    /// d(value)/dδ.
    pub d: f64,
    /// The sum of the magnitudes of the terms of `d`.
    pub m: f64,
    /// The roundings' bound, in units of 2^−p.
    pub e: f64,
}

impl Sh {
    /// A constant rounded once from an exact value.
    fn rounded(x: &Float) -> Self {
        let v = x.to_f64();
        Sh {
            v,
            d: 0.0,
            m: 0.0,
            e: v.abs(),
        }
    }

    /// A constant with a rounding bound `e` of its own.
    fn constant(v: f64, e: f64) -> Self {
        Sh {
            v,
            d: 0.0,
            m: 0.0,
            e,
        }
    }

    /// The exact zero.
    const ZERO: Sh = Sh {
        v: 0.0,
        d: 0.0,
        m: 0.0,
        e: 0.0,
    };

    fn add(self, o: Sh) -> Sh {
        let v = self.v + o.v;
        Sh {
            v,
            d: self.d + o.d,
            m: self.m + o.m,
            e: self.e + o.e + v.abs(),
        }
    }

    fn sub(self, o: Sh) -> Sh {
        let v = self.v - o.v;
        Sh {
            v,
            d: self.d - o.d,
            m: self.m + o.m,
            e: self.e + o.e + v.abs(),
        }
    }

    fn mul(self, o: Sh) -> Sh {
        let v = self.v * o.v;
        Sh {
            v,
            d: prod(self.d, o.v) + prod(self.v, o.d),
            m: prod(self.m, o.v.abs()) + prod(self.v.abs(), o.m),
            e: self.e * o.v.abs() + o.e * self.v.abs() + v.abs(),
        }
    }

    fn div(self, o: Sh) -> Sh {
        let v = self.v / o.v;
        Sh {
            v,
            d: (self.d - prod(v, o.d)) / o.v,
            m: (self.m + prod(v.abs(), o.m)) / o.v.abs(),
            e: (self.e + v.abs() * o.e) / o.v.abs() + v.abs(),
        }
    }

    /// The square root; at 0 a derivative (or an error) is infinite unless
    /// the argument has none.
    fn sqrt(self) -> Sh {
        let v = self.v.sqrt();
        let half = |x: f64| if x == 0.0 { 0.0 } else { x / (2.0 * v) };
        Sh {
            v,
            d: half(self.d),
            m: half(self.m),
            e: half(self.e) + v,
        }
    }

    /// Times a power of two (exact).
    fn scale(self, k: f64) -> Sh {
        Sh {
            v: self.v * k,
            d: self.d * k,
            m: self.m * k.abs(),
            e: self.e * k.abs(),
        }
    }

    fn neg(self) -> Sh {
        Sh {
            v: -self.v,
            d: -self.d,
            m: self.m,
            e: self.e,
        }
    }

    /// Whether every part is finite.
    pub fn is_finite(&self) -> bool {
        self.v.is_finite() && self.d.is_finite() && self.m.is_finite() && self.e.is_finite()
    }

    /// A bound on |d(value)/dδ|: the derivative and binary64's error in it
    /// (2^−45 of its terms' size: its few dozen operations' roundings).
    pub fn d_bound(&self) -> f64 {
        self.d.abs() + self.m * 2f64.powi(-45)
    }
}

/// A product where a zero factor wins over an infinite one (a derivative
/// that is not needed: δ exact).
fn prod(a: f64, b: f64) -> f64 {
    if a == 0.0 || b == 0.0 {
        0.0
    } else {
        a * b
    }
}

/// [`Dyn`]'s constants as [`Sh`] numbers, each with the roundings
/// [`Dyn::new`] made (built once per [`Dyn`]).
#[derive(Debug, Clone)]
pub struct Consts {
    s0: Sh,
    c0: Sh,
    q: [Sh; 3],
    h0: Sh,
    g: Sh,
    r: Sh,
    gr: Sh,
    m2: Sh,
    r1: Sh,
    r2: Sh,
    i2: Sh,
    m12: Sh,
    m12g: Sh,
    alpha: [Sh; 3],
    beta: [Sh; 3],
    gamma: [Sh; 3],
}

fn k_of(q: &[Sh; 3], x: Sh) -> Sh {
    q[2].mul(x).add(q[1]).mul(x).add(q[0])
}

impl Consts {
    /// The constants of `dy`.
    pub fn new(dy: &Dyn) -> Self {
        let c = Sh::rounded;
        // the constants as Dyn::new rounds them
        let th0 = c(&dy.th0);
        let (s0v, c0v) = (dy.s0.to_f64(), dy.c0.to_f64());
        // sin θ0 and cos θ0 of the rounded θ0, each rounded
        let s0 = Sh::constant(s0v, c0v.abs() * th0.e + s0v.abs());
        let c0 = Sh::constant(c0v, s0v.abs() * th0.e + c0v.abs());
        let q = [c(&dy.q[0]), c(&dy.q[1]), c(&dy.q[2])];
        let k0 = k_of(&q, c0);
        let h0 = if dy.h0.is_zero() {
            Sh::ZERO
        } else {
            // K(θ0) θ̇0 θ̇0, θ̇0 recovered from h0 (its own rounding counted)
            let td0 = (dy.h0.to_f64() / k0.v).sqrt();
            let td0 = Sh::constant(td0, td0);
            k0.mul(td0).mul(td0)
        };
        let (g, r) = (c(&dy.g), c(&dy.r));
        let gr = g.div(r);
        let (m1, m2, r1, r2) = (c(&dy.m1), c(&dy.m2), c(&dy.r1), c(&dy.r2));
        let i2 = c(&dy.i2);
        let m12 = m1.add(m2);
        let m12g = m12.mul(g);
        let alpha = [c(&dy.alpha[0]), c(&dy.alpha[1]), c(&dy.alpha[2])];
        let beta = [c(&dy.beta[0]), c(&dy.beta[1]), c(&dy.beta[2])];
        let gamma = [c(&dy.gamma[0]), c(&dy.gamma[1]), c(&dy.gamma[2])];
        Consts {
            s0,
            c0,
            q,
            h0,
            g,
            r,
            gr,
            m2,
            r1,
            r2,
            i2,
            m12,
            m12g,
            alpha,
            beta,
            gamma,
        }
    }
}

/// The columns of a row of the energy route, in the order of
/// [`crate::motion::COLUMNS`] from θ̇ to s12 (θ̇, θ̈, φ1, φ2, x1, x2, y2, ẋ1,
/// φ̇1, ẋ2, ẏ2, φ̇2, F1, N1, F21, N12, s1, s12): the formulas of
/// [`Dyn::state`], [`Dyn::positions_phi2`], [`Dyn::forces`] and the energy
/// route's `columns_at`, mirrored. `delta` is δ, `seed` its derivative (1,
/// or 0 where none is wanted), `t` the row's time (its conversion to p
/// bits counted as a rounding where `t_rounded`).
pub fn columns(dy: &Dyn, delta: f64, seed: f64, t: f64, t_rounded: bool) -> [Sh; 18] {
    let kc = dy.shadow.get_or_init(|| Consts::new(dy));
    // δ is exact here: its own error enters through the derivative
    let dl = Sh {
        v: delta,
        d: seed,
        m: seed.abs(),
        e: 0.0,
    };
    // --- Dyn::trig
    let half = dl.scale(0.5);
    let (hs, hc) = half.v.sin_cos();
    let sh = Sh {
        v: hs,
        d: hc * half.d,
        m: hc.abs() * half.m,
        e: hs.abs(),
    };
    let ch = Sh {
        v: hc,
        d: -hs * half.d,
        m: hs.abs() * half.m,
        e: hc.abs(),
    };
    let sm = kc.s0.mul(ch).add(kc.c0.mul(sh));
    let cm = kc.c0.mul(ch).sub(kc.s0.mul(sh));
    let s = sm.mul(ch).add(cm.mul(sh));
    let cs = cm.mul(ch).sub(sm.mul(sh));
    // --- Dyn::state
    let h = sm.mul(sh).mul(kc.gr).scale(4.0).add(kc.h0);
    let k = k_of(&kc.q, cs);
    let td2 = h.div(k);
    let td = td2.sqrt();
    let tdd = kc.q[2]
        .mul(cs)
        .scale(2.0)
        .add(kc.q[1])
        .mul(td2)
        .scale(0.5)
        .add(kc.gr)
        .mul(s)
        .div(k);
    let s_td2 = s.mul(td2);
    let mut v = [Sh::ZERO; 3];
    let mut a = [Sh::ZERO; 3];
    for i in 0..3 {
        let lin = kc.beta[i].mul(cs).add(kc.alpha[i]);
        v[i] = lin.mul(td).add(kc.gamma[i]);
        a[i] = lin.mul(tdd).sub(kc.beta[i].mul(s_td2));
    }
    let ds = cm.mul(sh).scale(2.0);
    // --- Dyn::positions_phi2: x1, φ1, (ψ2 − ψ0) + δ
    let tt = Sh::constant(t, if t_rounded { t.abs() } else { 0.0 });
    let mut pos = [Sh::ZERO; 3];
    for (i, o) in pos.iter_mut().enumerate() {
        *o = kc.gamma[i]
            .mul(tt)
            .add(kc.alpha[i].mul(dl))
            .add(kc.beta[i].mul(ds));
    }
    pos[2] = pos[2].add(dl);
    // --- Dyn::forces
    let ax = a[0];
    let tsq = td.mul(td);
    let n12 = kc.g.mul(cs).add(ax.mul(s)).sub(kc.r.mul(tsq)).mul(kc.m2);
    let f21 = match dy.contact {
        Contact::Roll => kc.i2.mul(a[2]).div(kc.r2),
        Contact::Slip => Sh::ZERO,
    };
    let f1 = match dy.floor {
        Floor::Slip => Sh::ZERO,
        _ => {
            let t1 = cs.mul(tdd).sub(s.mul(tsq)).mul(kc.r).mul(kc.m2);
            kc.m12.mul(ax).add(t1)
        }
    };
    let n1 = kc
        .m12g
        .sub(s.mul(tdd).add(cs.mul(tsq)).mul(kc.r).mul(kc.m2));
    // --- the energy route's columns_at
    let [xd, pd, sd] = v;
    let x2 = kc.r.mul(s).add(pos[0]);
    let y2 = kc.r.mul(cs).add(kc.r1);
    let x2d = kc.r.mul(cs).mul(td).add(xd);
    let y2d = kc.r.mul(s).mul(td).neg();
    let s1 = match dy.floor {
        Floor::Slip => xd.sub(kc.r1.mul(pd)),
        _ => Sh::ZERO,
    };
    let s12 = match dy.contact {
        Contact::Slip => kc.r.mul(td).add(kc.r2.mul(sd)).sub(kc.r1.mul(pd)),
        Contact::Roll => Sh::ZERO,
    };
    let phi2_dot = sd.add(td);
    [
        td, tdd, pos[1], pos[2], pos[0], x2, y2, xd, pd, x2d, y2d, phi2_dot, f1, n1, f21, n12, s1,
        s12,
    ]
}
