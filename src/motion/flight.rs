//! The free flight after separation, in closed form, to the first impact.
//!
//! With the contact open, cylinder 2 is a free body: its centre follows the
//! parabola x2 = x2s + ẋ2s τ, y2 = y2s + ẏ2s τ − g τ²/2 and its spin is
//! constant. Cylinder 1 moves under its floor law alone: rolling (or held,
//! or on a frictionless floor) it keeps its velocities (no force is needed);
//! sliding on a Coulomb floor with slip speed s1 ≠ 0 it feels F1 = −μk m1 g σ,
//! so ẍ1 = −μk g σ, φ̈1 = μk g σ/(k1 r1) and ṡ1 = −μk g σ (1 + 1/k1) until
//! the slip stops at τ* = |s1|/(μk g (1 + 1/k1)); then it rolls on.
//!
//! First impact: cylinder 2 reaching the floor (y2 = r2, the larger root of
//! a quadratic) or touching cylinder 1 again (d(τ) = |C2 − C1|² − r² = 0, a
//! quartic in τ on each piece of cylinder 1's motion). On the first piece
//! d = a2 τ² + a3 τ³ + a4 τ⁴ (d and ḋ vanish at separation; a2 = r r̈_free is
//! 0 when the contact force vanishes entirely, as it does with Coulomb
//! friction): the contact opens only if the first nonzero of (a2, a3) is
//! positive — otherwise the free motion would interpenetrate and the
//! rigid-body model has no continuation (an error, never a silent number).

use super::ctx::Ctx;
use super::mode::{Kind, Mode, Phase, State, Surface};
use super::point::{col, Point, TwoState};
use super::EventRec;
use crate::error::{Error, Result};
use crate::integrate::solve::Sample;
use crate::mechanics::system::{self as sy, System};
use crate::model::Which;
use rug::Float;

/// The state just before the first impact.
#[derive(Debug, Clone)]
pub struct Impact {
    /// What cylinder 2 hits.
    pub surface: Surface,
    /// Time.
    pub t: Float,
    /// Cylinder 1's centre x.
    pub x1: Float,
    /// Cylinder 2's centre.
    pub x2: Float,
    /// See `x2`.
    pub y2: Float,
    /// ẋ1.
    pub vx1: Float,
    /// φ̇1 (clockwise).
    pub phi1_dot: Float,
    /// ẋ2.
    pub vx2: Float,
    /// ẏ2.
    pub vy2: Float,
    /// ψ̇2 (cylinder 2's counter-clockwise spin, constant in flight).
    pub psi2_dot: Float,
}

impl Impact {
    /// Cylinder 2 landing on the floor while still touching cylinder 1 (the
    /// state `s` of a closed mode, `at` its columns).
    pub fn in_contact(sys: &System, s: &Sample, at: &Point) -> Impact {
        let p = sys.prec;
        let th = &s.q[sy::th(0)];
        let (sn, cs) = th.clone().sin_cos(Float::new(p));
        let r = &s.q[sy::rr(0)];
        let thd = &s.v[sy::th(0)];
        let vx1 = Float::with_val(p, &s.v[sy::X1]);
        Impact {
            surface: Surface::FloorInContact,
            t: at.t.clone(),
            x1: at.x1.clone(),
            x2: at.x2.clone(),
            y2: at.y2.clone(),
            vx2: Float::with_val(p, r * &cs) * thd + &vx1,
            vx1,
            phi1_dot: Float::with_val(p, &s.v[sy::PHI1]),
            vy2: -(Float::with_val(p, r * &sn) * thd),
            psi2_dot: Float::with_val(p, &s.v[sy::psi(0)]),
        }
    }
}

/// The free flight from separation.
#[derive(Debug, Clone)]
pub struct Flight {
    p: u32,
    ts: Float,
    m1: Float,
    m2: Float,
    i1: Float,
    i2: Float,
    r1: Float,
    g: Float,
    fixed: bool,
    // cylinder 1 at separation
    x1: Float,
    vx1: Float,
    phi1: Float,
    w1: Float,
    /// ẍ1 and φ̈1 while its floor slips, and the slip's end τ*.
    a1: Float,
    al1: Float,
    tau_stick: Option<Float>,
    mu_k_m1g: Float,
    s1: Float,
    // cylinder 2 at separation
    x2: Float,
    y2: Float,
    vx2: Float,
    vy2: Float,
    /// x2 − x1 and ẋ2 − ẋ1 at separation, from the line of centres
    /// (r sin θ, r θ̇ cos θ): the relative motion is never the difference
    /// of the two centres' abscissae, which a fast spin ω0 makes as large
    /// as ω0 r1 t while their difference stays of the size of r.
    dx: Float,
    dvx: Float,
    psi2: Float,
    w2: Float,
    work: Float,
    mode_floor: State,
    /// φ1 and φ̇1 are 0 by structure ([`crate::model::Model::spins_never_turned`],
    /// the held floor aside: its own mask below).
    no_spin: bool,
    /// The first impact.
    pub impact: Impact,
}

impl Flight {
    /// The flight from the separation state `s` (of `mode` in `sys`).
    ///
    /// Errors: a free motion that would interpenetrate at once, a cylinder 2
    /// already on the floor, an undecidable leading term.
    pub fn new(ctx: &Ctx, sys: &System, mode: Mode, s: &Sample, at: &Point) -> Result<Self> {
        let p = sys.prec;
        let f = |x: &Float| Float::with_val(p, x);
        let q = &s.q;
        let v = &s.v;
        let th = &q[sy::th(0)];
        let r = f(&q[sy::rr(0)]);
        let (sn, cs) = th.clone().sin_cos(Float::new(p));
        let thd = &v[sy::th(0)];
        let g = f(&sys.g);
        let (m1, m2) = (f(&sys.m[0]), f(&sys.m[1]));
        let (i1, i2) = (f(&sys.inertia[0]), f(&sys.inertia[1]));
        let r1 = f(&sys.rho[0]);
        let r2 = f(&sys.rho[1]);
        let x1 = f(&q[sy::X1]);
        let vx1 = f(&v[sy::X1]);
        let dx = Float::with_val(p, &r * &sn);
        let dvx = Float::with_val(p, &r * &cs) * thd;
        let x2 = Float::with_val(p, &dx + &x1);
        let y2 = Float::with_val(p, &r * &cs) + &q[sy::Y1];
        let vx2 = Float::with_val(p, &dvx + &vx1);
        let vy2 = -(Float::with_val(p, &r * &sn) * thd);
        // cylinder 1 alone on the floor
        let s1 = f(&at.s1);
        // a floor whose slip ends at the separation itself rolls on
        let tiny = Float::with_val(p, Float::with_val(p, &g * &r).sqrt()) * &ctx.rel_tiny;
        let sticking = matches!(mode.floor, State::Stick | State::Held)
            || Float::with_val(p, s1.abs_ref()) <= tiny;
        let mut a1 = ctx.floor_accel(sys, q, v, sticking);
        let mut al1 = Float::new(p);
        let mut tau_stick = None;
        let mu_k_m1g = Float::with_val(p, &ctx.mu_k[0] * &m1) * &g;
        if !a1.is_zero() {
            // φ̈1 = −r1 F1/I1 with F1 = m1 ẍ1
            al1 = -(Float::with_val(p, &a1 * &m1) * &r1) / &i1;
            let sdot = Float::with_val(p, &a1 - Float::with_val(p, &r1 * &al1));
            let tau = Float::with_val(p, s1.abs_ref()) / Float::with_val(p, sdot.abs_ref());
            tau_stick = Some(tau);
        }
        if ctx.held {
            a1 = Float::new(p);
        }
        // landing on the floor: y2 + vy2 τ − g τ²/2 = r2
        let h = Float::with_val(p, &y2 - &r2);
        if !h.is_sign_positive() || h.is_zero() {
            return Err(Error::not_physical(
                "at separation cylinder 2 already touches the floor",
            ));
        }
        let disc = Float::with_val(p, vy2.square_ref()) + Float::with_val(p, &g * &h) * 2u32;
        let tau_floor = (Float::with_val(p, disc.sqrt()) + &vy2) / &g;
        // (held: the flight's mask below has it already)
        let no_spin = ctx.model.spins_never_turned().0 && !ctx.held;
        let mut fl = Flight {
            no_spin,
            p,
            ts: f(&s.t),
            m1,
            m2,
            i1,
            i2,
            r1: r1.clone(),
            g: g.clone(),
            fixed: ctx.held,
            x1,
            vx1,
            phi1: f(&q[sy::PHI1]),
            w1: f(&v[sy::PHI1]),
            a1,
            al1,
            tau_stick,
            mu_k_m1g,
            s1,
            x2,
            y2,
            vx2,
            vy2,
            dx,
            dvx,
            psi2: f(&q[sy::psi(0)]),
            w2: f(&v[sy::psi(0)]),
            work: f(&s.work),
            mode_floor: if sticking && mode.floor != State::Held {
                State::Stick
            } else {
                mode.floor
            },
            impact: Impact {
                surface: Surface::Floor,
                t: Float::new(p),
                x1: Float::new(p),
                x2: Float::new(p),
                y2: Float::new(p),
                vx1: Float::new(p),
                phi1_dot: Float::new(p),
                vx2: Float::new(p),
                vy2: Float::new(p),
                psi2_dot: Float::new(p),
            },
        };
        // touching cylinder 1 again
        let tau_c = fl.recontact(&r, &tau_floor, ctx)?;
        let (surface, tau) = match tau_c {
            Some(tc) if tc < tau_floor => (Surface::Cylinder, tc),
            _ => (Surface::Floor, tau_floor),
        };
        let t_imp = Float::with_val(p, &fl.ts + &tau);
        let (x1i, vx1i, _, w1i) = fl.body1(&tau);
        let (x2i, y2i) = fl.body2(&tau);
        let vy2i = Float::with_val(p, &fl.vy2 - Float::with_val(p, &fl.g * &tau));
        fl.impact = Impact {
            surface,
            t: t_imp,
            x1: x1i,
            x2: x2i,
            y2: y2i,
            vx1: vx1i,
            phi1_dot: w1i,
            vx2: fl.vx2.clone(),
            vy2: vy2i,
            psi2_dot: fl.w2.clone(),
        };
        Ok(fl)
    }

    /// Cylinder 1 at flight time τ: (x1, ẋ1, φ1, φ̇1).
    fn body1(&self, tau: &Float) -> (Float, Float, Float, Float) {
        let p = self.p;
        let tt = match &self.tau_stick {
            Some(ts) if tau > ts => ts.clone(),
            _ => tau.clone(),
        };
        let rest = Float::with_val(p, tau - &tt);
        let half = |a: &Float| Float::with_val(p, a * Float::with_val(p, tt.square_ref())) / 2u32;
        let x = Float::with_val(p, &self.vx1 * &tt) + &self.x1 + half(&self.a1);
        let vx = Float::with_val(p, &self.a1 * &tt) + &self.vx1;
        let ph = Float::with_val(p, &self.w1 * &tt) + &self.phi1 + half(&self.al1);
        let w = Float::with_val(p, &self.al1 * &tt) + &self.w1;
        let x = x + Float::with_val(p, &vx * &rest);
        let ph = ph + Float::with_val(p, &w * &rest);
        (x, vx, ph, w)
    }

    /// x2 − x1 and ẋ2 − ẋ1 at flight time τ, from their values at
    /// separation: Δx = Δx0 + Δẋ0 τ − ẍ1 (tt²/2 + tt (τ − tt)) with tt the
    /// part of τ cylinder 1 spends sliding (its velocity terms cancel
    /// exactly, never through the centres' abscissae).
    fn relative_x(&self, tau: &Float) -> (Float, Float) {
        let p = self.p;
        let tt = match &self.tau_stick {
            Some(ts) if tau > ts => ts.clone(),
            _ => tau.clone(),
        };
        let rest = Float::with_val(p, tau - &tt);
        let mut x = Float::with_val(p, &self.dvx * tau) + &self.dx;
        let mut vx = self.dvx.clone();
        if !self.a1.is_zero() {
            let k = Float::with_val(p, tt.square_ref()) / 2u32 + Float::with_val(p, &tt * &rest);
            x -= Float::with_val(p, &self.a1 * &k);
            vx -= Float::with_val(p, &self.a1 * &tt);
        }
        (x, vx)
    }

    /// Cylinder 2's centre at flight time τ.
    fn body2(&self, tau: &Float) -> (Float, Float) {
        let p = self.p;
        let x = Float::with_val(p, &self.vx2 * tau) + &self.x2;
        let y = Float::with_val(p, &self.vy2 * tau) + &self.y2
            - Float::with_val(p, &self.g * Float::with_val(p, tau.square_ref())) / 2u32;
        (x, y)
    }

    /// The first τ in (0, τ_floor) at which the surfaces touch again.
    fn recontact(&self, r: &Float, tau_floor: &Float, ctx: &Ctx) -> Result<Option<Float>> {
        let p = self.p;
        // first piece: Δ = Δ0 + Δ1 τ + Δ2 τ², d = |Δ|² − r² with d(0) = ḋ(0) = 0
        let d0 = (self.dx.clone(), Float::with_val(p, &self.y2 - &self.r1));
        let d1 = (self.dvx.clone(), self.vy2.clone());
        let d2 = (
            -Float::with_val(p, &self.a1 / 2u32),
            -Float::with_val(p, &self.g / 2u32),
        );
        let dot = |a: &(Float, Float), b: &(Float, Float)| {
            Float::with_val(p, &a.0 * &b.0) + Float::with_val(p, &a.1 * &b.1)
        };
        let mut a2 = dot(&d1, &d1) + dot(&d0, &d2) * 2u32;
        let mut a3 = dot(&d1, &d2) * 2u32;
        let a4 = dot(&d2, &d2);
        let scale = Float::with_val(p, &self.g * r);
        let tiny = Float::with_val(p, &scale * &ctx.rel_tiny);
        if Float::with_val(p, a2.abs_ref()) <= tiny {
            a2 = Float::new(p);
        }
        if Float::with_val(p, a3.abs_ref()) <= Float::with_val(p, &tiny / &ctx.ts) {
            a3 = Float::new(p);
        }
        let end1 = match &self.tau_stick {
            Some(ts) if ts < tau_floor => ts.clone(),
            _ => tau_floor.clone(),
        };
        let lead = if !a2.is_zero() { &a2 } else { &a3 };
        if lead.is_zero() {
            return Err(Error::NotConverged {
                quantity: "separation".into(),
                requested: 0,
                reached: "the free relative motion's leading terms vanish".into(),
                detail: "whether the cylinders part cannot be decided at this precision".into(),
            });
        }
        if lead.is_sign_negative() {
            return Err(Error::NotConverged {
                quantity: "separation".into(),
                requested: 0,
                reached: format!(
                    "at separation (t = {}) the free motion would move the cylinders into each other",
                    crate::numeric::decimal::to_sig(&self.ts, 12)
                ),
                detail: "N12 = 0 while the contact cannot open: no consistent continuation of \
                         the rigid-body model"
                    .into(),
            });
        }
        // roots of a2 + a3 τ + a4 τ² on (0, end1]
        if !a2.is_zero() && a3.is_sign_negative() {
            let disc = Float::with_val(p, a3.square_ref()) - Float::with_val(p, &a2 * &a4) * 4u32;
            if disc.is_sign_positive() {
                let root =
                    (-Float::with_val(p, &a3) - disc.sqrt()) / Float::with_val(p, &a4 * 2u32);
                if root > 0 && root <= end1 {
                    return Ok(Some(root));
                }
            }
        }
        // second piece (cylinder 1 rolls on): scan and bisect d(τ)
        if let Some(ts) = &self.tau_stick {
            if ts < tau_floor {
                let d = |tau: &Float| -> Float {
                    let (dx, _) = self.relative_x(tau);
                    let (_, y2) = self.body2(tau);
                    let dy = Float::with_val(p, &y2 - &self.r1);
                    Float::with_val(p, dx.square_ref()) + Float::with_val(p, dy.square_ref())
                        - Float::with_val(p, r.square_ref())
                };
                let n = 512u32;
                let span = Float::with_val(p, tau_floor - ts);
                let mut a = ts.clone();
                for k in 1..=n {
                    let b = Float::with_val(p, &span * k) / n + ts;
                    if !d(&b).is_sign_positive() {
                        let (mut lo, mut hi) = (a, b);
                        for _ in 0..(p + 8) {
                            let mid = Float::with_val(p, &lo + &hi) / 2u32;
                            if d(&mid).is_sign_positive() {
                                lo = mid;
                            } else {
                                hi = mid;
                            }
                        }
                        return Ok(Some(hi));
                    }
                    a = b;
                }
            }
        }
        Ok(None)
    }

    /// Events inside the flight before the impact: the floor's slip ending.
    pub fn events(&self) -> Vec<EventRec> {
        let p = self.p;
        let mut out = Vec::new();
        if let Some(ts) = &self.tau_stick {
            let t = Float::with_val(p, &self.ts + ts);
            if t < self.impact.t {
                out.push(EventRec {
                    kind: Kind::Stick,
                    which: Some(Which::Floor),
                    phase: Some(Phase::Flight {
                        floor: State::Stick,
                    }),
                    at: self.point_with(&t, ts, Some(true)),
                    t_err: Float::new(p),
                    theta_err: Float::new(p),
                    after: Some(self.point_with(&t, ts, Some(false))),
                    also: Vec::new(),
                });
            }
        }
        out
    }

    /// Every column at time t (separation ≤ t ≤ impact).
    pub fn point(&self, t: &Float) -> Point {
        let tau = Float::with_val(self.p, t - &self.ts);
        self.point_with(t, &tau, None)
    }

    /// [`Flight::point`] at flight time `tau` (t − the separation's), with
    /// cylinder 1's floor sliding or stuck as `slipping` says (None: as τ
    /// against the stick time τ* says). At the stick event itself the two
    /// one-sided limits: sliding (F1 = m1 a1) just before, stuck (F1 = 0)
    /// just after — the event's state after was the state before (τ* − τ
    /// rounded below τ*), and a row just past the stick that a run placed
    /// before it took F1 = μk m1 g as verified.
    fn point_with(&self, t: &Float, tau: &Float, slipping: Option<bool>) -> Point {
        let p = self.p;
        let tau = tau.clone();
        let (x1, vx1, phi1, w1) = self.body1(&tau);
        let (x2, y2) = self.body2(&tau);
        let vy2 = Float::with_val(p, &self.vy2 - Float::with_val(p, &self.g * &tau));
        let slipping = slipping.unwrap_or(match &self.tau_stick {
            Some(ts) => tau < *ts,
            None => false,
        });
        let ax1 = if slipping {
            self.a1.clone()
        } else {
            Float::new(p)
        };
        let (xx, xd) = self.relative_x(&tau);
        let yy = Float::with_val(p, &y2 - &self.r1);
        let yd = vy2.clone();
        let dd = Float::with_val(p, xx.square_ref()) + Float::with_val(p, yy.square_ref());
        let theta = Float::with_val(p, xx.atan2_ref(&yy));
        let num = Float::with_val(p, &xd * &yy) - Float::with_val(p, &xx * &yd);
        let theta_dot = Float::with_val(p, &num / &dd);
        // θ̈ = (Ẍ Y − X Ÿ)/D − 2 θ̇ (X Ẋ + Y Ẏ)/D, Ẍ = −ẍ1, Ÿ = −g
        let xdd = -ax1.clone();
        let ydd = -self.g.clone();
        let n2 = Float::with_val(p, &xdd * &yy) - Float::with_val(p, &xx * &ydd);
        let rad = Float::with_val(p, &xx * &xd) + Float::with_val(p, &yy * &yd);
        let theta_ddot = (n2 - Float::with_val(p, &theta_dot * &rad) * 2u32) / &dd;
        let psi2 = Float::with_val(p, &self.w2 * &tau) + &self.psi2;
        let phi2 = Float::with_val(p, &psi2 + &theta);
        let phi2_dot = Float::with_val(p, &self.w2 + &theta_dot);
        // floor force and slip
        let (f1, s1, work) = if self.fixed {
            (Float::new(p), Float::new(p), self.work.clone())
        } else if let Some(ts) = &self.tau_stick {
            let tt = if slipping && tau < *ts {
                tau.clone()
            } else {
                ts.clone()
            };
            let sdot = Float::with_val(p, &self.a1 - Float::with_val(p, &self.r1 * &self.al1));
            let s1 = Float::with_val(p, &sdot * &tt) + &self.s1;
            let s1 = if slipping { s1 } else { Float::new(p) };
            // W = μk m1 g ∫|s1| dτ, |s1| falling linearly to 0 at τ*
            let abs0 = Float::with_val(p, self.s1.abs_ref());
            let absd = Float::with_val(p, sdot.abs_ref());
            let w = Float::with_val(p, &abs0 * &tt)
                - Float::with_val(p, &absd * Float::with_val(p, tt.square_ref())) / 2u32;
            let work = Float::with_val(p, &self.mu_k_m1g * &w) + &self.work;
            let f1 = if slipping {
                Float::with_val(p, &self.m1 * &self.a1)
            } else {
                Float::new(p)
            };
            (f1, s1, work)
        } else {
            let s1 = Float::with_val(p, &vx1 - Float::with_val(p, &self.r1 * &w1));
            let s1 = if self.mode_floor == State::Stick {
                Float::new(p)
            } else {
                s1
            };
            (Float::new(p), s1, self.work.clone())
        };
        let n1 = Float::with_val(p, &self.m1 * &self.g);
        let floor = if self.fixed {
            State::Held
        } else if slipping || (self.tau_stick.is_none() && self.mode_floor != State::Stick) {
            self.mode_floor
        } else {
            State::Stick
        };
        let mut zero = (1 << col!("F21")) | (1 << col!("N12")) | (1 << col!("s12"));
        // F1 = 0 by structure unless the floor slides with Coulomb friction:
        // held, frictionless, or rolling alone (no horizontal load); it was
        // reported as "0 within 2.8e-48", which no purely relative tolerance
        // (check --atol 0) could judge
        if !(self.tau_stick.is_some() && slipping) {
            zero |= 1 << col!("F1");
        }
        // cylinder 1 never spun (slip_slip from rest: "phi1 0 within" before)
        if self.no_spin {
            zero |= (1 << col!("phi1")) | (1 << col!("phi1_dot"));
        }
        // a held cylinder 1 does not move: "0 within 1.7e-55" before
        if self.fixed {
            zero |= (1 << col!("x1"))
                | (1 << col!("phi1"))
                | (1 << col!("x1_dot"))
                | (1 << col!("phi1_dot"));
        }
        if matches!(floor, State::Stick | State::Held) {
            zero |= 1 << col!("s1");
        }
        if self.work.is_zero() && self.tau_stick.is_none() {
            zero |= 1 << col!("work");
        }
        // energy T + V
        let half = |m: &Float, v: &Float| {
            Float::with_val(p, m * Float::with_val(p, v.square_ref())) / 2u32
        };
        let mut energy = half(&self.m1, &vx1) + half(&self.i1, &w1);
        energy += half(&self.m2, &self.vx2);
        energy += half(&self.m2, &vy2);
        energy += half(&self.i2, &self.w2);
        // heights above cylinder 1's centre (System::energy's zero): m1's
        // is 0, cylinder 1 on the floor
        let h2 = Float::with_val(p, &y2 - &self.r1);
        energy += Float::with_val(p, &self.m2 * &h2) * &self.g;
        Point {
            state: TwoState {
                t: Float::with_val(p, t),
                theta,
                theta_dot,
                theta_ddot,
                phi1,
                phi2,
                x1,
                x2,
                y2,
                x1_dot: vx1,
                phi1_dot: w1,
                x2_dot: self.vx2.clone(),
                y2_dot: vy2,
                phi2_dot,
                f1,
                n1,
                f21: Float::new(p),
                n12: Float::new(p),
            },
            s1,
            s12: Float::new(p),
            work,
            energy,
            phase: Phase::Flight { floor },
            err: None,
            exact_zero: zero,
            diff_weight: 1,
        }
    }
}
