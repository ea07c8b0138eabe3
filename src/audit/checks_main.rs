//! Checks of section 2 (both contacts rolling), eqs. (1)–(37), and
//! footnotes 6 and 8.

use super::corrected;
use super::ctx::Ctx;
use super::finding::{Finding, RootRow, Tally};
use super::forms::{calls, definitions};
use super::forms::{
    check, corrected, gen, other, printed, rest, rest_kick, sample, On, Sampled, REST,
};
use super::points::{with_k, Point};
use super::separation::first_root;
use super::truth::{self, Case, StartKind, Sys, PREC};
use crate::error::Result;
use crate::mechanics::Reduced;
use crate::model::{Contact, Floor};
// residuals are measurements, not bounds: quoted to nearest
use crate::numeric::decimal::short_near as short;
use crate::paper::{sec2, Sym, X};
use rug::Rational;

use Contact::Roll as CRoll;
use Floor::Roll as FRoll;

/// Runs `f` on every sample of the cases of `pts`.
pub(super) fn over<F>(
    cx: &mut Ctx,
    pts: &[Point],
    floor: Floor,
    contact: Contact,
    start: StartKind,
    timed: bool,
    mut f: F,
) -> Result<()>
where
    F: FnMut(&Case, &Sym),
{
    for p in pts {
        let c = cx.case(p, floor, contact, start, timed)?;
        for y in &c.syms {
            f(&c, y);
        }
    }
    Ok(())
}

/// A residual printed as text.
pub(super) fn res_text(x: &X) -> String {
    short(&x.0)
}

pub fn eq2(cx: &mut Ctx) -> Result<Finding> {
    let f = check(cx, rest_kick, |_, y| {
        let [a, b, d] = sec2::eq2(y);
        let psi = &y.phi2 - &y.th;
        let one = y.r1.n(1);
        vec![
            printed("φ2 = r1(φ1 − θ)/r2", a, &y.phi2, &one),
            printed("φ2 − θ = (r1/r2)φ1 − (r/r2)θ", b, &psi, &one),
            printed("φ2 − θ = (r1 φ1 − r θ)/r2", d, &psi, &one),
        ]
    })?;
    Ok(f.with_note("positions from the reduced dynamics (x1, φ1, ψ2 = φ2 − θ integrated in closed form; kick starts at the oracle's times)"))
}

pub fn eq3(cx: &mut Ctx) -> Result<Finding> {
    let mut f = Finding::default();
    for p in cx.general() {
        let c = cx.case(&p, FRoll, CRoll, StartKind::General, false)?;
        for y in &c.syms {
            let y0 = c.sym0.as_ref().unwrap_or(y);
            let v = sec2::eq3(y, &y0.c);
            let truth = truth::v(y) - truth::v(y0);
            f.printed.add("V", &c.name, &v, &truth, &c.scales.energy);
            // energy conservation with this V and the mechanics' kinetic energy
            let e = truth::t(y) + &v - truth::t(y0);
            f.printed
                .add_res("T + V conserved", &c.name, e.abs() / &c.scales.energy);
        }
    }
    Ok(f)
}

pub fn eq5(cx: &mut Ctx) -> Result<Finding> {
    check(cx, gen, |c, y| {
        let [a, b] = sec2::eq5(y);
        let (t1, e) = (truth::t1(y), &c.scales.energy);
        vec![
            printed("m1 ẋ1²/2 + I1 φ̇1²/2", a, &t1, e),
            printed("((1 + k1)/2) m1 r1² φ̇1²", b, &t1, e),
        ]
    })
}

pub fn eq6(cx: &mut Ctx) -> Result<Finding> {
    check(cx, gen, |c, y| {
        let [a, b] = sec2::eq6(y);
        let (t2, e) = (truth::t2(y), &c.scales.energy);
        vec![
            printed("with I2", a, &t2, e),
            printed("with k2 m2 r2²", b, &t2, e),
        ]
    })
}

pub fn eq7(cx: &mut Ctx) -> Result<Finding> {
    let f = check(cx, gen, |c, y| {
        let [_, xd] = sec2::eq7(y);
        vec![printed(
            "ẋ2 = r1 φ̇1 + r cos θ θ̇",
            xd,
            &truth::x2d(y),
            &c.scales.mom,
        )]
    })?;
    Ok(f.with_note("x2 = x1 + r sin θ is the geometry (the definition of θ); its rate is checked with the mechanics' ẋ1 = r1 φ̇1"))
}

pub fn eq8(cx: &mut Ctx) -> Result<Finding> {
    let f = check(cx, gen, |c, y| {
        let [_, yd] = sec2::eq8(y);
        let w = &c.scales.omega * &c.scales.len;
        vec![printed("ẏ2 = −r sin θ θ̇", yd, &truth::y2d(y), &w)]
    })?;
    Ok(f.with_note("y2 = r1 + r cos θ is the geometry"))
}

pub fn eq9(cx: &mut Ctx) -> Result<Finding> {
    check(cx, gen, |c, y| {
        let truth = &y.phi2d - &y.thd;
        vec![printed("φ̇2 − θ̇", sec2::eq9(y), &truth, &c.scales.omega)]
    })
}

pub fn eq10(cx: &mut Ctx) -> Result<Finding> {
    check(cx, gen, |c, y| {
        let [a, b] = sec2::eq10(y);
        let (t2, e) = (truth::t2(y), &c.scales.energy);
        vec![
            printed("expanded", a, &t2, e),
            printed("collected", b, &t2, e),
        ]
    })
}

pub fn eq11(cx: &mut Ctx) -> Result<Finding> {
    check(cx, gen, |c, y| {
        vec![printed("T", sec2::eq11(y), &truth::t(y), &c.scales.energy)]
    })
}

pub fn eq12(cx: &mut Ctx) -> Result<Finding> {
    check(cx, gen, |c, y| {
        let p = sec2::eq12(y);
        let truth = truth::momentum(Sys::Main, y, crate::paper::appendix::QP1);
        let s = &c.scales.angmom;
        let mut v = vec![printed("= ∂T/∂φ̇1", p.clone(), &truth, s)];
        if let Some(y0) = &c.sym0 {
            v.push(printed(
                "= constant (its value at t = 0)",
                p,
                &sec2::eq12(y0),
                s,
            ));
        }
        v
    })
}

pub fn eq13(cx: &mut Ctx) -> Result<Finding> {
    let f = check(cx, gen, |c, y| {
        let [a, b] = sec2::eq13(y);
        let (px, m) = (truth::px(y), &c.scales.mom);
        vec![
            printed("with ẋ1", a, &px, m),
            printed("with r1 φ̇1", b, &px, m),
        ]
    })?;
    Ok(f.with_note("true P_x = m1 ẋ1 + m2 ẋ2"))
}

pub fn eq15(cx: &mut Ctx) -> Result<Finding> {
    check(cx, gen, |c, y| {
        let [a, b] = sec2::eq15(y);
        let (l2, s) = (truth::l2(y), &c.scales.angmom);
        vec![
            printed("k2 m2 r2² (φ̇2 − θ̇)", a, &l2, s),
            printed("k2 m2 r2 (r1 φ̇1 − r θ̇)", b, &l2, s),
        ]
    })
}

pub fn eq16(cx: &mut Ctx) -> Result<Finding> {
    check(cx, gen, |c, y| {
        let p = sec2::eq16(y, &truth::px(y), &truth::l1(y), &truth::l2(y));
        let truth = truth::momentum(Sys::Main, y, crate::paper::appendix::QP1);
        vec![printed(
            "r1 P_x + L1 + (r1/r2) L2",
            p,
            &truth,
            &c.scales.angmom,
        )]
    })
}

pub fn eq17(cx: &mut Ctx) -> Result<Finding> {
    let f = check(cx, gen, |c, y| {
        let [a, b] = sec2::eq17(y);
        let w = &c.scales.omega;
        vec![
            printed("form 1", a, &y.phi1d, w),
            printed("with A", b, &y.phi1d, w),
        ]
    })?;
    Ok(f.with_note("ω0 ≠ 0 and θ̇0 ≠ 0 at every point: ω0 is φ̇1 at θ̇ = 0"))
}

pub fn eq18(cx: &mut Ctx) -> Result<Finding> {
    check(cx, gen, |c, y| {
        vec![printed("φ̈1", sec2::eq18(y), &y.phi1dd, &c.scales.accel)]
    })
}

pub fn eq20(cx: &mut Ctx) -> Result<Finding> {
    let f = check(cx, rest_kick, |_, y| {
        vec![printed("φ1", sec2::eq20(y), &y.phi1, &y.r1.n(1))]
    })?;
    Ok(f.with_note("kick starts: θ0 = 0 with θ̇0 ≠ 0 and ω0 ≠ 0, t from the oracle's energy quadrature (60 digits)"))
}

pub fn eq21(cx: &mut Ctx) -> Result<Finding> {
    let s = sample(cx, rest_kick, |_, y| {
        let [a, b] = sec2::eq21(y);
        let one = y.r1.n(1);
        vec![
            printed("(r1/r2)(φ1 − θ)", a, &y.phi2, &one),
            printed("(r1/r2) ω0 − …", b, &y.phi2, &one),
            corrected("(r1/r2) ω0 t − …", corrected::eq21(y), &y.phi2, &one),
        ]
    })?;
    Ok(s.corrected("φ2 = (r1/r2) ω0 t − (A r/r2)(sin θ − k2 θ) − (r1/r2) θ")
        .with_note("the printed ω0 lacks its factor t (dimensionally wrong); it matters only when ω0 ≠ 0, which the kick starts have and the sentence's 'from rest' excludes"))
}

pub fn eq22(cx: &mut Ctx) -> Result<Finding> {
    let f = check(cx, rest, |c, y| {
        vec![printed("= 0", sec2::eq22(y), &y.r1.zero(), &c.scales.accel)]
    })?;
    Ok(f.with_note("evaluated with the mechanics' θ̇ from rest at the top (ω0 = 0); equivalently K(cos θ) = 1 + k2 − A(cos θ − k2)²"))
}

pub fn eq23(cx: &mut Ctx) -> Result<Finding> {
    let mut s = Sampled::default();
    s.sample(cx, &gen(cx), |c, y| {
        let [a, _] = sec2::eq23(y);
        vec![printed(
            "first form (any start)",
            a,
            &y.thdd,
            &c.scales.accel,
        )]
    })?;
    s.sample(cx, &rest(cx), |c, y| {
        let [a, b] = sec2::eq23(y);
        let acc = &c.scales.accel;
        vec![
            printed("first form (any start)", a, &y.thdd, acc),
            printed("second form, (3 − 2 cos θ)", b, &y.thdd, acc),
            corrected(
                "second form, (2 − k2 − cos θ)",
                corrected::eq23(y),
                &y.thdd,
                acc,
            ),
        ]
    })?;
    Ok(s.corrected("θ̈ = [1 + k2 − A(cos θ − k2)(2 − k2 − cos θ)] / [1 + k2 − A(cos θ − k2)²]² (g/r) sin θ")
        .with_note("the second form substitutes θ̇² = 2(g/r)(1 − cos θ)/K from (22) into the first: K − 2A(cos θ − k2)(1 − cos θ) = 1 + k2 − A(cos θ − k2)(2 − k2 − cos θ); the printed (3 − 2 cos θ) agrees with it only where cos θ = 1 + k2 or cos θ = k2"))
}

pub fn eq24(cx: &mut Ctx) -> Result<Finding> {
    let mut f = Finding::default();
    let pts = cx.general();
    let one = Rational::from(1);
    for p in &pts {
        let p1 = with_k(p, &p.params.k1, &one, &format!("{} k2=1", p.name));
        let model = truth::model_of(&p1, FRoll, CRoll, StartKind::Rest)?;
        let red = Reduced::new(&model)?;
        // θ̈ = (g/r) θ / K(1) + O(θ³) from rest: the exact linear coefficient
        let k1sum = Rational::from(&red.q[0] + &red.q[1]) + &red.q[2];
        let pr = model.params();
        let coef = Rational::from(&pr.g / &pr.r()) / k1sum;
        let truth = X::q(PREC, &coef);
        let y = Sym {
            g: X::q(PREC, &pr.g),
            r1: X::q(PREC, &pr.r1),
            r2: X::q(PREC, &pr.r2),
            ..dummy_sym()
        };
        let scale = X::q(PREC, &Rational::from(&pr.g / &pr.r()));
        f.printed.add(
            "coefficient g/(2r)",
            &p1.name,
            &sec2::eq24(&y),
            &truth,
            &scale,
        );
    }
    f.note("compared with the exact linearisation θ̈ = (g/r) θ / K(1) of the reduced dynamics (K(1) = 2 exactly when k2 = 1); 'Mathieu' is a misnomer: Mathieu's equation has a periodic coefficient, this is the plain inverted pendulum");
    Ok(f)
}

/// A `Sym` of zeros (for formulas that need only a few parameters).
pub(super) fn dummy_sym() -> Sym {
    let z = X::int(PREC, 0);
    Sym {
        m1: z.clone(),
        m2: z.clone(),
        r1: z.clone(),
        r2: z.clone(),
        k1: z.clone(),
        k2: z.clone(),
        g: z.clone(),
        omega0: z.clone(),
        t: z.clone(),
        x1: z.clone(),
        y1: z.clone(),
        phi1: z.clone(),
        phi2: z.clone(),
        th: z.clone(),
        s: z.clone(),
        c: z.clone(),
        r: z.clone(),
        x1d: z.clone(),
        y1d: z.clone(),
        phi1d: z.clone(),
        phi2d: z.clone(),
        thd: z.clone(),
        rd: z.clone(),
        x1dd: z.clone(),
        y1dd: z.clone(),
        phi1dd: z.clone(),
        phi2dd: z.clone(),
        thdd: z.clone(),
        rdd: z.clone(),
        x2d: z.clone(),
        y2d: z.clone(),
        y2dd: z.clone(),
        f1: z.clone(),
        n1: z.clone(),
        f21: z.clone(),
        f12: z.clone(),
        n12: z.clone(),
        lam: [z.clone(), z.clone(), z.clone(), z],
    }
}

pub fn eq25(cx: &mut Ctx) -> Result<Finding> {
    check(cx, rest, |c, y| {
        let [xc, yc] = sec2::eq25(y);
        let m = &y.m1 + &y.m2;
        let r = y.rsum();
        let x2 = &y.x1 + &r * &y.s;
        let y2 = &y.r1 + &r * &y.c;
        let tx = (&y.m1 * &y.x1 + &y.m2 * x2) / &m;
        let ty = (&y.m1 * &y.r1 + &y.m2 * y2) / m;
        vec![
            printed("x_cm", xc, &tx, &c.scales.len),
            printed("y_cm", yc, &ty, &c.scales.len),
        ]
    })
}

pub fn eq26(cx: &mut Ctx) -> Result<Finding> {
    let f = check(cx, gen, |c, y| {
        let [a, b] = sec2::eq26(y);
        let s = &c.scales.force;
        vec![
            printed("with ẍ1", a, &y.f1, s),
            printed("with r1 φ̈1", b, &y.f1, s),
        ]
    })?;
    Ok(f.with_note(
        "F1 from the Lagrange-multiplier system in six coordinates (an independent route)",
    ))
}

pub fn eq27(cx: &mut Ctx) -> Result<Finding> {
    check(cx, gen, |c, y| {
        vec![printed("N1", sec2::eq27(y), &y.n1, &c.scales.force)]
    })
}

pub fn eq28(cx: &mut Ctx) -> Result<Finding> {
    let labels = [
        "(I2/r2)(φ̈2 − θ̈)",
        "k2 m2 r2 (φ̈2 − θ̈)",
        "k2 m2 (r1 φ̈1 − r θ̈)",
    ];
    let s = sample(cx, gen, |c, y| {
        let s = &c.scales.force;
        let minus = -&y.f21;
        let mut v = Vec::new();
        for (label, m) in labels.iter().zip(sec2::eq28(y)) {
            v.push(printed(*label, m.clone(), &y.f21, s));
            v.push(other(*label, m, &minus, s));
        }
        v
    })?;
    let mut f = s.f;
    f.convention = Some(
        "F21 is the component of cylinder 1's force on cylinder 2 along (cos θ, −sin θ), the direction in which the point of contact moves round cylinder 1 as θ grows".into(),
    );
    if let Some(m) = s.other.max() {
        f.note(format!(
            "along the opposite direction the residual is {} (the text does not state the direction)",
            res_text(&m)
        ));
    }
    Ok(f)
}

pub fn eq29(cx: &mut Ctx) -> Result<Finding> {
    let s = sample(cx, gen, |c, y| {
        let truth = -(y.i1() * &y.phi1dd);
        let e = &c.scales.energy;
        // F12 read as the tangential force on cylinder 1 along (−cos θ, sin θ): F12 = +F21
        let mut yc = y.clone();
        yc.f12 = y.f21.clone();
        let [m0, m1, m2, m3] = sec2::eq29(&yc);
        let [lit, ..] = sec2::eq29(y);
        vec![
            printed("(F1 + F12) r1, F12 = +F21", m0, &truth, e),
            printed("(F1 − F21) r1", m1, &truth, e),
            printed("−I1 φ̈1", m2, &truth, e),
            printed("−k1 m1 r1² φ̈1", m3, &truth, e),
            other("(F1 + F12) r1, F12 = −F21", lit, &truth, e),
            corrected("(F1 + F21) r1", corrected::eq29(y), &truth, e),
        ]
    })?;
    let literal = s.other.max();
    let mut f = s.corrected("(F1 + F21) r1 = −I1 φ̈1 = −k1 m1 r1² φ̈1");
    if let Some(m) = literal {
        f.note(format!(
            "with the text's F21 = −F12 the first member equals the second and fails too (residual {})",
            res_text(&m)
        ));
    }
    Ok(f.with_note("the torque of the contact force about cylinder 1's axis is +r1 F21 counter-clockwise (with F21 as in (28)), so the balance is r1(F1 + F21) = −I1 φ̈1; this is what (30) and the appendix's (104) (−r1 λ1 − r1 λ2 = I1 φ̈1) say, so (28), (30) and (104) are right and the second member of (29) has the wrong sign"))
}

pub fn eq30(cx: &mut Ctx) -> Result<Finding> {
    let f = check(cx, gen, |c, y| {
        vec![printed("F1", sec2::eq30(y), &y.f1, &c.scales.force)]
    })?;
    Ok(f.with_note(
        "follows from (28) and the corrected (29); with the printed (F1 − F21) it would not",
    ))
}

fn eq31_32(cx: &mut Ctx, which: usize) -> Result<Finding> {
    let (form, mid): (fn(&Sym) -> [X; 2], &str) = if which == 31 {
        (sec2::eq31, "N1 − m1 g + F12 sin θ")
    } else {
        (sec2::eq32, "F1 − m1 ẍ1 − F12 cos θ")
    };
    let s = sample(cx, gen, |c, y| {
        let truth = if which == 31 {
            &y.n12 * &y.c
        } else {
            &y.n12 * &y.s
        };
        let mut yc = y.clone();
        yc.f12 = y.f21.clone();
        let [m0, m1] = form(&yc);
        let [lit, _] = form(y);
        let sc = &c.scales.force;
        vec![
            printed(mid, m0, &truth, sc),
            printed("m2 [...]", m1, &truth, sc),
            other(mid, lit, &truth, sc),
        ]
    })?;
    let mut f = s.f;
    f.convention = Some(
        "F12 is the tangential force on cylinder 1 measured along (−cos θ, sin θ), i.e. F12 = +F21 as numbers (F21 = −F12 holds only as vectors)".into(),
    );
    if let Some(m) = s.other.max() {
        f.note(format!(
            "with the text's F21 = −F12 (as numbers along one direction) the middle member fails: residual {}",
            res_text(&m)
        ));
    }
    Ok(f.with_note("N12 and F21 from the Lagrange-multiplier system; the last member holds with F21 as in (28)"))
}

pub fn eq33(cx: &mut Ctx) -> Result<Finding> {
    let s = sample(cx, gen, |c, y| {
        let s = &c.scales.force;
        vec![
            printed("g cos θ + r1 sin θ φ̇1 − r θ̇²", sec2::eq33(y), &y.n12, s),
            corrected(
                "m2(g cos θ + r1 sin θ φ̈1 − r θ̇²)",
                corrected::eq33(y),
                &y.n12,
                s,
            ),
        ]
    })?;
    Ok(s.corrected("N12 = m2 (g cos θ + r1 sin θ φ̈1 − r θ̇²)")
        .with_note("cos θ·(31) + sin θ·(32) gives m2(g cos θ + r1 sin θ φ̈1 − r θ̇²): the printed form lacks the factor m2 and has φ̇1 for φ̈1; the appendix's (88) and (112) have it right"))
}

/// Separation checks shared by (34), (37), (89): residual at the oracle's θs
/// and the roots of the printed and corrected conditions.
#[allow(clippy::too_many_arguments)]
pub(super) fn separation_rows<P, C>(
    cx: &mut Ctx,
    floor: Floor,
    contact: Contact,
    pts: &[Point],
    f: &mut Finding,
    corr: Option<&mut Tally>,
    printed: P,
    corrected: C,
) -> Result<()>
where
    P: Fn(&Sym) -> [X; 2],
    C: Fn(&Sym) -> [X; 2],
{
    let mut corr = corr;
    for p in pts {
        let ths = cx.theta_s(p, floor, contact)?;
        let case = cx.case(p, floor, contact, StartKind::Rest, false)?;
        let ys = cx.sym_at(p, floor, contact, &ths)?;
        let at = format!("{} at θs", case.name);
        let [l, r] = printed(&ys);
        f.printed.add("at θs", &at, &r, &l, &(&ys.g * 1i32));
        if let Some(t) = corr.as_deref_mut() {
            let [l, r] = corrected(&ys);
            t.add("at θs", &at, &r, &l, &(&ys.g * 1i32));
        }
        let pr = first_root(|th| {
            let st = case.dynm.state(&th.0);
            match case.sym(&st, &rug::Float::new(PREC)) {
                Ok(y) => {
                    let [l, r] = printed(&y);
                    l - r
                }
                Err(_) => th.zero(),
            }
        });
        let co = if corr.is_some() {
            first_root(|th| {
                let st = case.dynm.state(&th.0);
                match case.sym(&st, &rug::Float::new(PREC)) {
                    Ok(y) => {
                        let [l, r] = corrected(&y);
                        l - r
                    }
                    Err(_) => th.zero(),
                }
            })
        } else {
            None
        };
        f.roots.push(RootRow {
            case: format!("{} {floor}/{contact}", p.name),
            printed: pr,
            corrected: co,
            oracle: ths,
        });
    }
    Ok(())
}

pub fn eq34(cx: &mut Ctx) -> Result<Finding> {
    let mut f = Finding::default();
    let mut corr = Tally::default();
    let pts = cx.general();
    separation_rows(
        cx,
        FRoll,
        CRoll,
        &pts,
        &mut f,
        Some(&mut corr),
        sec2::eq34,
        |y| [y.rsum() * y.thd.sq(), corrected::eq34(y)],
    )?;
    f.corrected = Some(("r θ̇s² = g cos θs + r1 sin θs φ̈1".into(), corr));
    f.note("residuals relative to g at the oracle's θs (from rest at the top); the printed φ̇1 makes the condition depend on ω0, which θs does not; (37) and (89), derived the other way, have φ̈1 and 'confirm' the corrected form");
    Ok(f)
}

pub fn eq35(cx: &mut Ctx) -> Result<Finding> {
    let f = check(cx, gen, |_, y| {
        let [a, b] = sec2::eq35(y);
        let (t, g) = (-&y.x1dd, &y.g * 1i32);
        vec![printed("−ẍ1", a, &t, &g), printed("−r1 φ̈1", b, &t, &g)]
    })?;
    Ok(f.with_note("the x component of g_eff is −ẍ1 by definition (frame of cylinder 1's axis); checked: ẍ1 = r1 φ̈1 on the motion"))
}

/// The fixed-lower-cylinder points: k2 of each random point and footnote 8's values.
pub(super) fn fixed_points(cx: &Ctx) -> Vec<Point> {
    let mut v: Vec<Point> = cx.random();
    if let Some(p) = v.first().cloned() {
        for (n, d) in [(0, 1), (1, 2), (2, 5)] {
            let k2 = Rational::from((n, d));
            let name = format!("k2={}", crate::exact::rational_text(&k2));
            v.push(with_k(&p, &p.params.k1, &k2, &name));
        }
    }
    v
}

pub fn eq36(cx: &mut Ctx) -> Result<Finding> {
    let mut f = Finding::default();
    let pts = fixed_points(cx);
    for p in &pts {
        let ths = cx.theta_s(p, Floor::Fixed, CRoll)?;
        let k2 = X::q(PREC, &p.params.k2);
        let c = sec2::eq36(&k2);
        f.printed.add(
            "cos θs",
            &format!("{} fixed/roll", p.name),
            &c,
            &ths.cos(),
            &c.n(1),
        );
        f.roots.push(RootRow {
            case: format!(
                "{} fixed/roll (k2 = {})",
                p.name,
                crate::exact::rational_text(&p.params.k2)
            ),
            printed: Some(c.acos()),
            corrected: None,
            oracle: ths,
        });
    }
    f.note(branch_point_note()?);
    Ok(f)
}

/// Eq. (36)'s condition r θ̇² = g cos θ is where cylinder 2, falling
/// freely, would leave a cylinder 1 that does not accelerate. On a held
/// cylinder it is N12 = 0 itself; on the paper's other cases it is met
/// *before* N12 = 0 while the cylinders still press on each other: from
/// there parting is as lawful as staying together (the branch point θ*), and
/// the paper's θs is the end of the closed branch only.
fn branch_point_note() -> Result<String> {
    use crate::model::{Ideal, Params, Start};
    use crate::oracle::ideal::Oracle;
    let mut rows = Vec::new();
    for (floor, contact, name) in [
        (Floor::Roll, Contact::Roll, "sec. 2, roll/roll"),
        (Floor::Slip, Contact::Roll, "sec. 3.2, slip/roll"),
        (Floor::Roll, Contact::Slip, "sec. 3.3, roll/slip"),
        (Floor::Slip, Contact::Slip, "sec. 3.1, slip/slip"),
        (Floor::Fixed, Contact::Roll, "footnote 8, fixed/roll"),
    ] {
        let m = Ideal::new(
            Params::identical_solid(),
            floor,
            contact,
            Start::rest(crate::exact::Exact::zero()),
        )?;
        let mut o = Oracle::new(&m, 12)?;
        let ths = o.separation_angle()?;
        let star = o.branch_point()?;
        rows.push(match star {
            Some(st) => format!("{name}: θ* = {} < θs = {}", st.text, ths.text),
            None => format!("{name}: none (unique up to θs = {})", ths.text),
        });
    }
    Ok(format!(
        "the condition r θ̇² = g cos θ of this footnote is where cylinder 2, falling freely, \
         would leave a cylinder 1 that does not accelerate; on a held cylinder it is N12 = 0 \
         itself, but on a lower cylinder free to move under a rolling contact it is met before N12 = 0 while the cylinders \
         still press on each other: from there (the branch point θ*) parting is as lawful as \
         staying together in the rigid-body model, and the θs of eqs. (34), (37) and sec. 3.2 is \
         the end of the closed branch only (reached when the contact persists, the limit of stiff \
         compliant contact). Identical solid cylinders from rest at the top (limits θ0 → 0+): {}; \
         a frictionless contact or a held cylinder has no branch point",
        rows.join("; ")
    ))
}

pub fn eq37(cx: &mut Ctx) -> Result<Finding> {
    let mut f = check(cx, gen, |_, y| {
        // at every angle: each member is N12/m2 + r θ̇² (so r θ̇² = member ⇔ N12 = 0)
        let truth = &y.n12 / &y.m2 + y.rsum() * y.thd.sq();
        let [_, m1, m2, m3] = sec2::eq37(y);
        let g = &y.g * 1i32;
        vec![
            printed("r̂·g_eff (any angle)", m1, &truth, &g),
            printed("g cos θ + r1 sin θ φ̈1 (any angle)", m2, &truth, &g),
            printed("g cos θ − r A sin θ[…] (any angle)", m3, &truth, &g),
        ]
    })?;
    let pts = cx.general();
    let cond = |y: &Sym| {
        let m = sec2::eq37(y);
        [m[0].clone(), m[3].clone()]
    };
    separation_rows(cx, FRoll, CRoll, &pts, &mut f, None, cond, cond)?;
    f.note("each member equals N12/m2 + r θ̇² at every angle (N12 from the multipliers), so the condition is N12 = 0; its root equals the oracle's θs");
    f.note("for identical solid cylinders (m1 = m2, r1 = r2, k1 = k2 = 1/2) the root is exactly π/3 (see README), so 'intricate' has at least one simple case");
    Ok(f)
}

pub fn fn6(cx: &mut Ctx) -> Result<Finding> {
    let pts = vec![cx.point("S")?, cx.point("I(1/2)")?];
    let on = |_: &Ctx| On {
        pts,
        fc: (FRoll, CRoll),
        starts: REST,
    };
    let s = sample(cx, on, |c, y| {
        let (t, a) = (y.thd.sq(), &c.scales.accel);
        vec![
            printed("θ̇² without g", sec2::fn6(y), &t, a),
            corrected("θ̇² with g", corrected::fn6(y), &t, a),
        ]
    })?;
    Ok(s.corrected("θ̇² = 12 g (1 − cos θ)/a(17 + 4 cos θ − 4 cos²θ)").with_note(
        "point S has g = 1, where the printed form happens to hold; I(1/2) has g = 49/5, a = 2/3",
    ))
}

pub fn fn8(cx: &mut Ctx) -> Result<Finding> {
    let mut f = Finding::default();
    let pts = fixed_points(cx);
    over(
        cx,
        &pts,
        Floor::Fixed,
        CRoll,
        StartKind::Rest,
        false,
        |c, y| {
            let [_, e] = sec2::fn8(y);
            f.printed.add(
                "(1 + k2) r θ̇²/2 = g(1 − cos θ)",
                &c.name,
                &e,
                &y.r1.zero(),
                &c.scales.energy,
            );
        },
    )?;
    for p in &pts {
        let ths = cx.theta_s(p, Floor::Fixed, CRoll)?;
        let ys = cx.sym_at(p, Floor::Fixed, CRoll, &ths)?;
        let [a, _] = sec2::fn8(&ys);
        f.printed.add(
            "r θ̇s² = g cos θs at θs",
            &format!("{} fixed/roll", p.name),
            &a,
            &ys.r1.zero(),
            &ys.g,
        );
    }
    // the three values
    let p0 = cx.random().into_iter().next();
    if let Some(p0) = p0 {
        for (kn, kd, cn, cd) in sec2::FN8_VALUES {
            let k2 = Rational::from((kn, kd));
            let stated = X::q(PREC, &Rational::from((cn, cd)));
            let formula = sec2::eq36(&X::q(PREC, &k2));
            let name = format!("k2={}", crate::exact::rational_text(&k2));
            let p = with_k(&p0, &p0.params.k1, &k2, &name);
            let ths = cx.theta_s(&p, Floor::Fixed, CRoll)?;
            let label = format!("cos θs = {cn}/{cd}");
            f.printed
                .add(&label, "2/(3 + k2)", &stated, &formula, &stated.n(1));
            f.printed.add(
                &label,
                &format!("{} fixed/roll", p.name),
                &stated,
                &ths.cos(),
                &stated.n(1),
            );
            if kn == 0 {
                // k2 → 0 is also the point (or frictionless body) sliding off a fixed log
                let ths = cx.theta_s(&p, Floor::Fixed, Contact::Slip)?;
                f.printed.add(
                    &label,
                    &format!("{} fixed/slip", p.name),
                    &stated,
                    &ths.cos(),
                    &stated.n(1),
                );
            }
        }
    }
    Ok(f)
}

definitions! {
    eq1: "the rolling constraint of the lower cylinder: a model assumption, which the mechanics imposes";
    eq4: "defines the canonical momentum of φ1; its value is checked as eq. (12)";
    eq14: "defines L1 = I1 φ̇1, the spin angular momentum of cylinder 1";
    eq19: "defines the constant A";
}

calls! {
    eq31 => eq31_32(31);
    eq32 => eq31_32(32);
}
