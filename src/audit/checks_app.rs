//! Checks of the appendix (Lagrange multipliers), eqs. (56)–(114), and
//! footnotes 1, 3, 15.

use super::checks_main::{over, res_text, separation_rows};
use super::corrected;
use super::ctx::Ctx;
use super::finding::{Finding, Tally};
use super::forms::gen as on_general;
use super::forms::rest as on_rest;
use super::forms::{calls, check, corrected, definitions, other, printed, sample, Form, Sampled};
use super::truth::{self, lagrange_lhs, momentum, random_state, Case, Scales, StartKind, Sys};
use crate::error::Result;
use crate::model::{Contact, Floor};
use crate::paper::appendix::{self as app, Jac, QP1, QP2, QR, QTH, QX1, QY1};
use crate::paper::{Sym, X};

/// Both rolling, general start: the appendix's motion.
fn gen<F: FnMut(&Case, &Sym, &Jac)>(cx: &mut Ctx, mut f: F) -> Result<()> {
    let pts = cx.general();
    over(
        cx,
        &pts,
        Floor::Roll,
        Contact::Roll,
        StartKind::General,
        false,
        |c, y| {
            let jac = truth::constraint_jacobian(y);
            f(c, y, &jac)
        },
    )
}

/// Random states of the six coordinates embedded in `sys`, four per random point.
fn random_states(cx: &mut Ctx, sys: Sys) -> Result<Vec<(String, Sym, Scales)>> {
    let mut out = Vec::new();
    for (i, p) in cx.random().iter().enumerate() {
        let case = cx.case(p, Floor::Roll, Contact::Roll, StartKind::Rest, false)?;
        let Some(template) = case.syms.first() else {
            continue;
        };
        for k in 0..4u64 {
            let y = random_state(template, sys, 1000 * (i as u64 + 1) + k);
            out.push((
                format!("{} random {:?} state {}", p.name, sys, k + 1),
                y,
                case.scales.clone(),
            ));
        }
    }
    Ok(out)
}

fn kinetic(cx: &mut Ctx, sys: Sys, form: fn(&Sym) -> X, whole: bool) -> Result<Finding> {
    let mut f = Finding::default();
    for (at, y, sc) in random_states(cx, sys)? {
        let t = if whole { truth::t(&y) } else { truth::t2(&y) };
        f.printed.add(
            if whole { "T" } else { "T2" },
            &at,
            &form(&y),
            &t,
            &sc.energy,
        );
    }
    f.note("at random states of the coordinates and rates (off the motion), against ½m|v|² + ½Iω² of the bodies");
    Ok(f)
}

/// A Lagrange equation `lhs = members…` of system `sys`, coordinate `u`, on
/// the general motion.
fn lagrange(
    cx: &mut Ctx,
    sys: Sys,
    u: usize,
    labels: &[&str],
    members: fn(&Sym, &Jac) -> [X; 2],
    torque: bool,
) -> Result<Finding> {
    let mut f = Finding::default();
    gen(cx, |c, y, jac| {
        let lhs = lagrange_lhs(sys, y, u);
        let sc = if torque {
            &c.scales.energy
        } else {
            &c.scales.force
        };
        for (v, l) in members(y, jac).iter().zip(labels) {
            f.printed.add(l, &c.name, v, &lhs, sc);
        }
    })?;
    f.note("left side: d/dt ∂L/∂q̇ − ∂L/∂q of the bodies in these coordinates, on the motion of the reduced dynamics; multipliers λ1…λ4 = F1, F21, N12, N1 from the six-coordinate multiplier system");
    Ok(f)
}

fn jacobian_row(
    cx: &mut Ctx,
    row: usize,
    cols: &[usize],
    printed: fn(&Sym) -> Vec<X>,
) -> Result<Finding> {
    let mut f = Finding::default();
    for (at, y, _) in random_states(cx, Sys::A5)? {
        let jac = truth::constraint_jacobian(&y);
        for (k, v) in printed(&y).iter().enumerate() {
            let i = cols[k];
            f.printed.add(
                &format!("∂f{}/∂{}", row + 1, app::COORDS[i]),
                &at,
                v,
                &jac[row][i],
                &y.r1.n(1),
            );
        }
    }
    f.note("derivatives of the printed constraints (58)–(61), exact (they are linear)");
    Ok(f)
}

/// A named physical quantity of a state (label, value).
type Named = (&'static str, fn(&Sym) -> X);

/// A printed conjugate momentum p = `printed(y)` of coordinate `q` in system
/// `sys`, against ∂T/∂q̇ from the system's kinetic energy and, when given,
/// against a named physical momentum (`also`: label and value).
fn conjugate(
    cx: &mut Ctx,
    sys: Sys,
    q: usize,
    printed: fn(&Sym) -> X,
    also: Option<Named>,
) -> Result<Finding> {
    let label = match q {
        QX1 => "= ∂T/∂ẋ1",
        QP1 => "= ∂T/∂φ̇1",
        _ => "= ∂T/∂φ̇2",
    };
    let mut f = Finding::default();
    for (at, y, sc) in random_states(cx, sys)? {
        let scale = if q == QX1 { &sc.mom } else { &sc.angmom };
        let p = printed(&y);
        f.printed.add(label, &at, &p, &momentum(sys, &y, q), scale);
        if let Some((name, value)) = also {
            f.printed.add(name, &at, &p, &value(&y), scale);
        }
    }
    Ok(f)
}

pub fn eq64(cx: &mut Ctx) -> Result<Finding> {
    let mut s = Sampled::default();
    for (at, y, sc) in random_states(cx, Sys::A1)? {
        let m = momentum(Sys::A1, &y, QP1);
        let [a, b, c] = app::eq64(&y, &truth::l1(&y), &truth::l2(&y));
        let w = &sc.angmom;
        s.add(
            &at,
            vec![
                printed("(k1 m1 + k2 m2) r1² φ̇1 − k2 m2 r1 r θ̇", a, &m, w),
                printed("k1 m1 r1² φ̇1 + r1[k2 m2 (r1 φ̇1 − k2 m2 r θ̇)]", b, &m, w),
                printed("L1 + (r1/r2) L2", c, &m, w),
                corrected(
                    "k1 m1 r1² φ̇1 + r1 k2 m2 (r1 φ̇1 − r θ̇)",
                    corrected::eq64(&y),
                    &m,
                    w,
                ),
            ],
        );
    }
    Ok(s.corrected("p_φ1 = (k1 m1 + k2 m2) r1² φ̇1 − k2 m2 r1 r θ̇ = k1 m1 r1² φ̇1 + r1 k2 m2 (r1 φ̇1 − r θ̇) = L1 + (r1/r2) L2")
        .with_note("a misplaced bracket: the middle form multiplies r θ̇ by k2 m2 twice (it is not even dimensionally consistent); the first and last forms are right"))
}

/// A combination of momenta: printed forms vs the true value, constancy, and
/// zero from rest.
fn momentum_sum(
    cx: &mut Ctx,
    forms: fn(&Sym) -> Vec<X>,
    labels: &[&str],
    truth_of: fn(&Sym) -> X,
) -> Result<Finding> {
    let mut s = sample(cx, on_general, |c, y| {
        let (t, m) = (truth_of(y), &c.scales.mom);
        let mut v: Vec<Form> = forms(y)
            .into_iter()
            .zip(labels)
            .map(|(v, l)| printed(*l, v, &t, m))
            .collect();
        if let Some(y0) = &c.sym0 {
            v.push(printed(
                "constant (value at t = 0)",
                t.clone(),
                &truth_of(y0),
                m,
            ));
        }
        v.push(other("= 0", t.clone(), &t.zero(), m));
        v
    })?;
    s.sample(cx, &on_rest(cx), |c, y| {
        vec![printed(
            "= 0 (start from rest)",
            truth_of(y),
            &y.r1.zero(),
            &c.scales.mom,
        )]
    })?;
    let mut f = s.f;
    if let Some(m) = s.other.max() {
        f.note(format!(
            "'= 0' needs a start from rest (θ̇0 = 0, ω0 = 0), not only x1 = φ1 = θ = 0 as the text says: with the general starts the sum is a nonzero constant (relative size {})",
            res_text(&m)
        ));
    }
    Ok(f)
}

pub fn eq70(cx: &mut Ctx) -> Result<Finding> {
    let f = check(cx, on_general, |c, y| {
        let t = lagrange_lhs(Sys::A1, y, QP1) / &y.r1;
        let [a, b] = app::eq70(y);
        let s = &c.scales.force;
        vec![
            printed("−λ1", a, &t, s),
            printed("(k1 m1 + k2 m2) r1 φ̈1 − k2 m2 r θ̈", b, &t, s),
            printed(
                "λ1 = F1 of (30)",
                y.lam[0].clone(),
                &crate::paper::sec2::eq30(y),
                s,
            ),
        ]
    })?;
    Ok(f.with_note("the printed expression is −λ1 = −F1; 'which is the force F1 found in eq. (30)' refers to λ1"))
}

pub fn eq79(cx: &mut Ctx) -> Result<Finding> {
    let f = lam_expr(
        cx,
        Sys::A2,
        QP2,
        &["λ2", "k2 m2 r2 (φ̈2 − θ̈)", "k2 m2 (r1 φ̈1 − r θ̈)"],
        |y| app::eq79(y).to_vec(),
        true,
    )?;
    Ok(f.with_note("λ2 is F21 of (28) with the same convention (along (cos θ, −sin θ))"))
}

pub fn a3_v(cx: &mut Ctx) -> Result<Finding> {
    let mut f = Finding::default();
    for (at, y, sc) in random_states(cx, Sys::A3)? {
        f.printed
            .add("V", &at, &app::a3_v(&y), &truth::v(&y), &sc.energy);
    }
    f.note("with r a coordinate (A.3), against m2 g y2 relative to the top");
    Ok(f)
}

pub fn eq81(cx: &mut Ctx) -> Result<Finding> {
    let mut f = Finding::default();
    let mut literal = Tally::default();
    for (at, y, sc) in random_states(cx, Sys::A3)? {
        let m = momentum(Sys::A3, &y, QP1);
        // (13)'s expression with the coordinate r
        let px13 = (&y.m1 + &y.m2) * &y.x1d + &y.m2 * &y.r * &y.c * &y.thd;
        let [a, b] = app::eq81(&y, &px13, &truth::l1(&y));
        f.printed.add("form 1", &at, &a, &m, &sc.angmom);
        f.printed.add(
            "r1 P_x + L1 + m2 r1 ṙ sin θ, P_x of (13)",
            &at,
            &b,
            &m,
            &sc.angmom,
        );
        let [_, b2] = app::eq81(&y, &truth::px(&y), &truth::l1(&y));
        literal.add("with P_x = m1 ẋ1 + m2 ẋ2", &at, &b2, &m, &sc.angmom);
    }
    f.convention = Some(
        "P_x means the expression (13), (m1 + m2) ẋ1 + m2 r cos θ θ̇, without the ṙ term".into(),
    );
    f.reading = true;
    if let Some(m) = literal.max() {
        f.note(format!(
            "with P_x the total horizontal momentum m1 ẋ1 + m2 ẋ2 (which is what (100) calls P_x: it includes m2 ṙ sin θ) the term m2 r1 ṙ sin θ is counted twice: residual {}",
            res_text(&m)
        ));
    }
    Ok(f)
}

pub fn eq82(cx: &mut Ctx) -> Result<Finding> {
    let mut f = Finding::default();
    for (at, y, sc) in random_states(cx, Sys::A3)? {
        let m = momentum(Sys::A3, &y, QP2);
        let [a, b] = app::eq82(&y, &truth::l2(&y));
        f.printed.add("k2 m2 r2² (φ̇2 − θ̇)", &at, &a, &m, &sc.angmom);
        f.printed.add("L2", &at, &b, &m, &sc.angmom);
    }
    Ok(f)
}

fn eq84_86(cx: &mut Ctx, u: usize, k: usize, members: fn(&Sym, &Jac) -> [X; 2]) -> Result<Finding> {
    let mut f = Finding::default();
    let mut corr = Tally::default();
    let coord = app::COORDS[u];
    gen(cx, |c, y, jac| {
        let lhs = lagrange_lhs(Sys::A3, y, u);
        let m = members(y, jac);
        f.printed.add(
            &format!("λ3 ∂f3/∂{coord}"),
            &c.name,
            &m[0],
            &lhs,
            &c.scales.energy,
        );
        f.printed.add("0", &c.name, &m[1], &lhs, &c.scales.energy);
        corr.add(
            "with λ2",
            &c.name,
            &corrected::eq84_86(y)[k],
            &lhs,
            &c.scales.energy,
        );
    })?;
    // as printed it is right for a frictionless contact (sec. 3.3)
    let mut slip = Tally::default();
    let pts = cx.general();
    over(
        cx,
        &pts,
        Floor::Roll,
        Contact::Slip,
        StartKind::General,
        false,
        |c, y| {
            let jac = truth::constraint_jacobian(y);
            let lhs = lagrange_lhs(Sys::A3, y, u);
            slip.add("0", &c.name, &members(y, &jac)[1], &lhs, &c.scales.energy);
        },
    )?;
    let text = [
        "dp_φ1/dt = −r1 λ2",
        "dp_φ2/dt = r2 λ2",
        "d/dt ∂L/∂θ̇ − ∂L/∂θ = r1 λ2",
    ][k];
    f.corrected = Some((text.into(), corr));
    f.note("A.3 keeps φ2 as a coordinate, so the rolling constraint (59) is relaxed as well and its multiplier λ2 = F21 must appear, as in (75)–(77) (same momenta: (81), (82) equal (72), (73) at ṙ = 0); the printed 0 contradicts (75)–(77)");
    if let Some(m) = slip.max() {
        f.note(format!(
            "as printed it holds for a frictionless contact between the cylinders (F21 = 0, sec. 3.3): residual {}",
            res_text(&m)
        ));
    }
    Ok(f)
}

pub fn eq88(cx: &mut Ctx) -> Result<Finding> {
    let f = check(cx, on_general, |c, y| {
        let t = lagrange_lhs(Sys::A3, y, QR);
        let [a, b] = app::eq88(y);
        let s = &c.scales.force;
        vec![
            printed("first line", a, &t, s),
            printed("m2 [r1 sin θ φ̈1 − r θ̇² + g cos θ]", b.clone(), &t, s),
            printed("= N12", b, &y.n12, s),
        ]
    })?;
    Ok(f.with_note("agrees with the corrected (33), not the printed one"))
}

pub fn eq89(cx: &mut Ctx) -> Result<Finding> {
    let mut f = Finding::default();
    gen(cx, |c, y, _| {
        let truth = &y.n12 / &y.m2 + &y.r * y.thd.sq();
        let m = app::eq89(y);
        f.printed
            .add("second member (any angle)", &c.name, &m[1], &truth, &y.g);
        f.printed
            .add("third member (any angle)", &c.name, &m[2], &truth, &y.g);
    })?;
    let pts = cx.general();
    separation_rows(
        cx,
        Floor::Roll,
        Contact::Roll,
        &pts,
        &mut f,
        None,
        |y| {
            let m = app::eq89(y);
            [m[0].clone(), m[2].clone()]
        },
        |y| {
            let m = app::eq89(y);
            [m[0].clone(), m[2].clone()]
        },
    )?;
    f.note("slips that change no value: 'g cos θ' for g cos θs, and 'using eq. (17)' where (18) is used");
    Ok(f)
}

pub fn eq90(cx: &mut Ctx) -> Result<Finding> {
    let mut f = Finding::default();
    for (at, y, sc) in random_states(cx, Sys::A4)? {
        let [dt, dv] = app::eq90(&y);
        let mut y0 = y.clone();
        y0.y1d = y.r1.zero();
        let mut yv = y.clone();
        yv.y1 = y.r1.clone();
        f.printed
            .add("ΔT", &at, &dt, &(truth::t(&y) - truth::t(&y0)), &sc.energy);
        f.printed
            .add("ΔV", &at, &dv, &(truth::v(&y) - truth::v(&yv)), &sc.energy);
    }
    Ok(f)
}

pub fn eq91(cx: &mut Ctx) -> Result<Finding> {
    let mut f = Finding::default();
    for (at, y, sc) in random_states(cx, Sys::A4)? {
        let m = momentum(Sys::A4, &y, QP1);
        let [a, b] = app::eq91(&y, &truth::px(&y), &truth::l1(&y), &truth::l2(&y));
        f.printed.add("form 1", &at, &a, &m, &sc.angmom);
        f.printed
            .add("r1 P_x + L1 + (r1/r2) L2", &at, &b, &m, &sc.angmom);
    }
    Ok(f)
}

pub fn eq93(cx: &mut Ctx) -> Result<Finding> {
    let mut f = lagrange(cx, Sys::A4, QP1, &["λ4 ∂f3/∂φ1", "0"], app::eq93, true)?;
    f.note("a slip that changes no value: ∂f3/∂φ1 should read ∂f4/∂φ1 (both are 0); the text also announces 'four Lagrange equations' where there are three");
    Ok(f)
}

fn lam_expr(
    cx: &mut Ctx,
    sys: Sys,
    u: usize,
    labels: &[&str],
    forms: fn(&Sym) -> Vec<X>,
    per_r2: bool,
) -> Result<Finding> {
    check(cx, on_general, |c, y| {
        let mut t = lagrange_lhs(sys, y, u);
        if per_r2 {
            t = t / &y.r2;
        }
        forms(y)
            .into_iter()
            .zip(labels)
            .map(|(v, l)| printed(*l, v, &t, &c.scales.force))
            .collect()
    })
}

fn n1_forms(cx: &mut Ctx, forms: fn(&Sym) -> [X; 2]) -> Result<Finding> {
    check(cx, on_general, |c, y| {
        let [a, b] = forms(y);
        let s = &c.scales.force;
        vec![
            printed("(m1 + m2) g − m2 r (…)", a, &y.n1, s),
            printed("(m1 + m2) g + m2 ÿ2", b, &y.n1, s),
        ]
    })
}

pub fn eq98(cx: &mut Ctx) -> Result<Finding> {
    let mut s = Sampled {
        f: kinetic(cx, Sys::A5, app::eq98, true)?,
        ..Default::default()
    };
    for (at, y, sc) in random_states(cx, Sys::A5)? {
        let form = corrected(
            "T with m1 k1 r1²",
            corrected::eq98(&y),
            &truth::t(&y),
            &sc.energy,
        );
        s.add(&at, vec![form]);
    }
    Ok(s.corrected("the spin term of cylinder 1 is (m1 k1 r1²/2) φ̇1² (printed m1 k2 r1²)")
        .with_note("(101) has the right m1 k1 r1² φ̇1, which contradicts the printed (98); (101) is right"))
}

pub fn eq99(cx: &mut Ctx) -> Result<Finding> {
    let mut s = Sampled::default();
    for (at, y, sc) in random_states(cx, Sys::A5)? {
        let t = truth::v(&y);
        let mut ym = y.clone();
        ym.r = &y.r1 + &y.r2;
        s.add(
            &at,
            vec![
                printed("V", app::eq99(&y), &t, &sc.energy),
                corrected("V", corrected::eq99(&y), &t, &sc.energy),
                other(
                    "V on r = r1 + r2",
                    app::eq99(&ym),
                    &truth::v(&ym),
                    &sc.energy,
                ),
            ],
        );
    }
    let on = s.other.max();
    let mut f = s.corrected("V = m2 g (r cos θ − r1 − r2) + (m1 + m2) g (y1 − r1)");
    if let Some(m) = on {
        f.note(format!(
            "with r a coordinate, −m2 g r (1 − cos θ) has ∂V/∂r = −m2 g (1 − cos θ) instead of m2 g cos θ; on r = r1 + r2 it is right (residual {}) but (107) differentiates in r; the paper's own (112) uses the correct + m2 g cos θ and A.3 writes the correct V, so (99) is the slip",
            res_text(&m)
        ));
    }
    Ok(f)
}

pub fn eq104(cx: &mut Ctx) -> Result<Finding> {
    let mut f = lagrange(
        cx,
        Sys::A5,
        QP1,
        &["Σ λj ∂fj/∂φ1", "−r1 λ1 − r1 λ2"],
        app::eq104,
        true,
    )?;
    f.note("I1 φ̈1 = −r1 (F1 + F21): the torque balance that the printed (29) gets wrong");
    Ok(f)
}

pub fn eq112(cx: &mut Ctx) -> Result<Finding> {
    let mut f = lam_expr(
        cx,
        Sys::A5,
        QR,
        &["first line", "m2 (ẍ1 sin θ − r θ̇² + g cos θ)"],
        |y| app::eq112(y).to_vec(),
        false,
    )?;
    f.note("uses ∂V/∂r = m2 g cos θ, i.e. the correct V, not the printed (99)");
    Ok(f)
}

pub fn fn15(cx: &mut Ctx) -> Result<Finding> {
    let f = check(cx, on_general, |c, y| {
        let l2 = lagrange_lhs(Sys::A5, y, QTH) / &y.r1;
        let l1 = -(lagrange_lhs(Sys::A5, y, QP1) / &y.r1) - &l2;
        let s = &c.scales.force;
        vec![
            printed("F21 from (106)", l2, &y.f21, s),
            printed("F1 from (104)", l1, &y.f1, s),
        ]
    })?;
    Ok(f.with_note("λ2 = (θ equation)/r1, λ1 = −(φ1 equation)/r1 − λ2, against the multiplier system's F21 and F1"))
}

pub fn eq69(cx: &mut Ctx) -> Result<Finding> {
    momentum_sum(
        cx,
        |y| app::eq69(y, &truth::px(y), &truth::l1(y), &truth::l2(y)).to_vec(),
        &["p_x1 + p_φ1/r1 (63, 64)", "P_x + L1/r1 + L2/r2"],
        |y| momentum(Sys::A1, y, QX1) + momentum(Sys::A1, y, QP1) / &y.r1,
    )
}

pub fn eq78(cx: &mut Ctx) -> Result<Finding> {
    momentum_sum(
        cx,
        |y| {
            vec![
                app::eq78(y),
                truth::px(y) + truth::l1(y) / &y.r1 + truth::l2(y) / &y.r2,
            ]
        },
        &[
            "p_φ1/r1 + p_φ2/r2 (72, 73)",
            "= P_x + L1/r1 + L2/r2 once (59) holds",
        ],
        |y| momentum(Sys::A2, y, QP1) / &y.r1 + momentum(Sys::A2, y, QP2) / &y.r2,
    )
}

pub fn eq109(cx: &mut Ctx) -> Result<Finding> {
    momentum_sum(
        cx,
        |y| app::eq109(y, &truth::px(y), &truth::l1(y), &truth::l2(y)).to_vec(),
        &["p_x1 + p_φ1/r1 + p_φ2/r2 (100–102)", "P_x + L1/r1 + L2/r2"],
        |y| {
            momentum(Sys::A5, y, QX1)
                + momentum(Sys::A5, y, QP1) / &y.r1
                + momentum(Sys::A5, y, QP2) / &y.r2
        },
    )
}

definitions! {
    eq56: "Lagrange's equations: the method, not a formula of this problem";
    eq57: "the method of multipliers; its instances (66)–(68), (75)–(77), (84)–(87), (93)–(95), (103)–(108) are checked";
    eq58: "defines the constraint f1 (rolling on the floor, eq. 1)";
    eq59: "defines the constraint f2 (rolling contact, eq. 2)";
    eq60: "defines the constraint f3 (the cylinders touch)";
    eq61: "defines the constraint f4 (cylinder 1 on the floor)";
    fn1: "a remark on the admissible k (the mechanics takes any k ≥ 0; k2 > 1 is audited at P2, k1 > 1 at P4)";
    fn3: "a count, not a formula: 3n − n − n = n coordinates, one cyclic (φ1); consistent";
}

calls! {
    eq62 => kinetic(Sys::A1, app::eq62, false);
    eq63 => conjugate(Sys::A1, QX1, app::eq63, Some(("= P_x", truth::px)));
    eq65 => jacobian_row(0, &[QX1, QP1, QTH], |y| app::eq65(y).to_vec());
    eq66 => lagrange(Sys::A1, QX1, &["λ1 ∂f1/∂x1", "λ1"], app::eq66, false);
    eq67 => lagrange(Sys::A1, QP1, &["λ1 ∂f1/∂φ1", "−r1 λ1"], app::eq67, true);
    eq68 => lagrange(Sys::A1, QTH, &["λ1 ∂f1/∂θ", "0"], app::eq68, true);
    eq71 => kinetic(Sys::A2, app::eq71, false);
    eq72 => conjugate(Sys::A2, QP1, app::eq72, None);
    eq73 => conjugate(Sys::A2, QP2, app::eq73, None);
    eq74 => jacobian_row(1, &[QP1, QP2, QTH], |y| app::eq74(y).to_vec());
    eq75 => lagrange(Sys::A2, QP1, &["λ2 ∂f2/∂φ1", "−r1 λ2"], app::eq75, true);
    eq76 => lagrange(Sys::A2, QP2, &["λ2 ∂f2/∂φ2", "r2 λ2"], app::eq76, true);
    eq77 => lagrange(Sys::A2, QTH, &["λ2 ∂f2/∂θ", "r1 λ2"], app::eq77, true);
    eq80 => kinetic(Sys::A3, app::eq80, false);
    eq83 => jacobian_row(2, &[QP1, QP2, QTH, QR], |y| app::eq83(y).to_vec());
    eq84 => eq84_86(QP1, 0, app::eq84);
    eq85 => eq84_86(QP2, 1, app::eq85);
    eq86 => eq84_86(QTH, 2, app::eq86);
    eq87 => lagrange(Sys::A3, QR, &["λ3 ∂f3/∂r", "λ3"], app::eq87, false);
    eq92 => jacobian_row(3, &[QP1, QTH, QY1], |y| app::eq92(y).to_vec());
    eq94 => lagrange(Sys::A4, QTH, &["λ4 ∂f4/∂θ", "0"], app::eq94, true);
    eq95 => lagrange(Sys::A4, QY1, &["λ4 ∂f4/∂y1", "λ4"], app::eq95, false);
    eq96 => lam_expr(Sys::A4, QY1, &["λ4", "(m1 + m2) ÿ1 − …"], |y| app::eq96(y).to_vec(), false);
    eq97 => n1_forms(app::eq97);
    eq100 => conjugate(Sys::A5, QX1, app::eq100, Some(("= P_x", truth::px)));
    eq101 => conjugate(Sys::A5, QP1, app::eq101, Some(("= L1", truth::l1)));
    eq102 => conjugate(Sys::A5, QP2, app::eq102, Some(("= L2", truth::l2)));
    eq103 => lagrange(Sys::A5, QX1, &["Σ λj ∂fj/∂x1", "λ1"], app::eq103, false);
    eq105 => lagrange(Sys::A5, QP2, &["Σ λj ∂fj/∂φ2", "r2 λ2"], app::eq105, true);
    eq106 => lagrange(Sys::A5, QTH, &["Σ λj ∂fj/∂θ", "r1 λ2"], app::eq106, true);
    eq107 => lagrange(Sys::A5, QR, &["Σ λj ∂fj/∂r", "λ3"], app::eq107, false);
    eq108 => lagrange(Sys::A5, QY1, &["Σ λj ∂fj/∂y1", "λ4"], app::eq108, false);
    eq110 => lam_expr(Sys::A5, QX1, &["λ1", "(m1 + m2) ẍ1 + m2 (…)"], |y| app::eq110(y).to_vec(), false);
    eq111 => lam_expr(Sys::A5, QP2, &["λ2", "k2 m2 r2 (φ̈2 − θ̈)", "k2 m2 (r1 φ̈1 − r θ̈)"], |y| app::eq111(y).to_vec(), true);
    eq113 => lam_expr(Sys::A5, QY1, &["λ4", "(m1 + m2) ÿ1 − …"], |y| app::eq113(y).to_vec(), false);
    eq114 => n1_forms(app::eq114);
}
