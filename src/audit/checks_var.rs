//! Checks of section 3 (variants), eqs. (38)–(55), footnotes 11 and 12, and
//! the prose claims.

use super::checks_main::{fixed_points, separation_rows};
use super::corrected;
use super::ctx::Ctx;
use super::finding::{Finding, RootRow, Tally};
use super::forms::calls;
use super::forms::{check, printed, On, REST};
use super::points::{with_k, Point};
use super::separation::{first_root_below, first_root_cos};
use super::truth::{self, Case, StartKind, Sys, PREC};
use crate::error::Result;
use crate::exact::Exact;
use crate::mechanics::dynamics::Dyn;
use crate::mechanics::Reduced;
use crate::model::{Contact, Floor, Ideal, Params, Start};
use crate::paper::appendix::{QP1, QX1};
use crate::paper::{sec2, sec3, Sym, X};
use rug::{Float, Rational};

/// From rest at the top, the general points, one contact model.
fn rest(fc: (Floor, Contact)) -> impl FnOnce(&Ctx) -> On {
    move |cx| on_points(cx.general(), fc)
}

/// From rest at the top, the given points, one contact model.
fn on_points(pts: Vec<Point>, fc: (Floor, Contact)) -> On {
    On {
        pts,
        fc,
        starts: REST,
    }
}

const SS: (Floor, Contact) = (Floor::Slip, Contact::Slip);
const SR: (Floor, Contact) = (Floor::Slip, Contact::Roll);
const RS: (Floor, Contact) = (Floor::Roll, Contact::Slip);
const RR: (Floor, Contact) = (Floor::Roll, Contact::Roll);

fn kinetic(cx: &mut Ctx, fc: (Floor, Contact), form: fn(&Sym) -> X) -> Result<Finding> {
    let f = check(cx, rest(fc), |c, y| {
        vec![printed("T", form(y), &truth::t(y), &c.scales.energy)]
    })?;
    Ok(f.with_note("from rest (ω0 = 0): neither cylinder spins where its contact is frictionless"))
}

fn energy_zero(cx: &mut Ctx, fc: (Floor, Contact), form: fn(&Sym) -> X) -> Result<Finding> {
    let f = check(cx, rest(fc), |c, y| {
        vec![printed("= 0", form(y), &y.r1.zero(), &c.scales.accel)]
    })?;
    Ok(f.with_note("evaluated with the mechanics' θ̇, from rest at the top"))
}

fn geff(
    cx: &mut Ctx,
    fc: (Floor, Contact),
    forms: fn(&Sym) -> Vec<X>,
    labels: &[&str],
) -> Result<Finding> {
    check(cx, rest(fc), |_, y| {
        let t = -&y.x1dd;
        forms(y)
            .into_iter()
            .zip(labels)
            .map(|(v, l)| printed(*l, v, &t, &y.g))
            .collect()
    })
}

fn sep_form(cx: &mut Ctx, fc: (Floor, Contact), forms: fn(&Sym) -> [X; 3]) -> Result<Finding> {
    let mut f = check(cx, rest(fc), |_, y| {
        let truth = &y.n12 / &y.m2 + y.rsum() * y.thd.sq();
        let [_, m1, m2] = forms(y);
        vec![
            printed("r̂·g_eff (any angle)", m1, &truth, &y.g),
            printed("last form (any angle)", m2, &truth, &y.g),
        ]
    })?;
    let pts = cx.general();
    let cond = |y: &Sym| {
        let [m0, _, m2] = forms(y);
        [m0, m2]
    };
    separation_rows(cx, fc.0, fc.1, &pts, &mut f, None, cond, cond)?;
    Ok(f.with_note("each member equals N12/m2 + r θ̇² at every angle, so the condition is N12 = 0; its root equals the oracle's θs"))
}

pub fn eq39(cx: &mut Ctx) -> Result<Finding> {
    check(cx, rest(SS), |c, y| {
        let p = sec3::eq39(y);
        let m = &c.scales.mom;
        vec![
            printed(
                "= ∂T/∂ẋ1",
                p.clone(),
                &truth::momentum(Sys::NoFriction, y, QX1),
                m,
            ),
            printed("= P_x", p.clone(), &truth::px(y), m),
            printed("= 0", p, &y.r1.zero(), m),
        ]
    })
}

pub fn eq43(cx: &mut Ctx) -> Result<Finding> {
    let mut f = Finding::default();
    let mut corr = Tally::default();
    let pts = cx.general();
    let mut other = Vec::new();
    for p in &pts {
        let ths = cx.theta_s(p, SS.0, SS.1)?;
        let (m1, m2) = (X::q(PREC, &p.params.m1), X::q(PREC, &p.params.m2));
        let c = ths.cos();
        let at = format!("{} slip/slip at θs", p.name);
        let scale = &m1 + &m2;
        f.printed.add(
            "m2 cos²θs − (m1 + m2)(3 cos θs − 2)",
            &at,
            &sec3::eq43(&m1, &m2, &c),
            &c.zero(),
            &scale,
        );
        corr.add(
            "m2 cos³θs − (m1 + m2)(3 cos θs − 2)",
            &at,
            &corrected::eq43(&m1, &m2, &c),
            &c.zero(),
            &scale,
        );
        let pr = first_root_cos(|c| sec3::eq43(&m1, &m2, c));
        let co = first_root_cos(|c| corrected::eq43(&m1, &m2, c));
        let alt = first_root_below(&X::q(PREC, &Rational::from((3, 2))), |th| {
            sec3::eq43_cos_of_square(&m1, &m2, th)
        });
        other.push(format!(
            "{}: {}",
            p.name,
            alt.map(|a| crate::numeric::decimal::to_sig(&a.0, 12))
                .unwrap_or_else(|| "no root".into())
        ));
        f.roots.push(RootRow {
            case: format!(
                "{} slip/slip (m2/m1 = {})",
                p.name,
                crate::exact::rational_text(&Rational::from(&p.params.m2 / &p.params.m1))
            ),
            printed: pr,
            corrected: co,
            oracle: ths,
        });
    }
    f.corrected = Some(("m2 cos³θs = (m1 + m2)(3 cos θs − 2)".into(), corr));
    f.note("with P_x = 0 and (40), N12 = 0 reduces to m2 c³ − 3(m1 + m2) c + 2(m1 + m2) = 0 (c = cos θs); for m1 = m2 the root is c = √3 − 1, θs = 0.7494…, where the printed cos² gives 0.7014…");
    f.note(format!(
        "read as cos(θs²) the printed equation is no better; its roots: {}",
        other.join(", ")
    ));
    f.note("the sentence after (43) (fixed lower cylinder: cos θs = 2/3) holds for both forms as m1 → ∞; see p-fixed-slip");
    Ok(f)
}

pub fn eq45(cx: &mut Ctx) -> Result<Finding> {
    check(cx, rest(SR), |c, y| {
        let p = sec3::eq45(y);
        let m = &c.scales.mom;
        vec![
            printed("= ∂T/∂ẋ1", p.clone(), &truth::momentum(Sys::A1, y, QX1), m),
            printed("= P_x", p.clone(), &truth::px(y), m),
            printed("= 0", p, &y.r1.zero(), m),
        ]
    })
}

pub fn eq46(cx: &mut Ctx) -> Result<Finding> {
    check(cx, rest(SR), |c, y| {
        let [a, b] = sec3::eq46(y, &truth::l1(y), &truth::l2(y));
        let (m, s) = (truth::momentum(Sys::A1, y, QP1), &c.scales.angmom);
        vec![
            printed("= ∂T/∂φ̇1", a.clone(), &m, s),
            printed("= L1 + (r1/r2) L2", b, &m, s),
            printed("= 0", a, &y.r1.zero(), s),
        ]
    })
}

pub fn eq49(cx: &mut Ctx) -> Result<Finding> {
    let mut f = sep_form(cx, SR, sec3::eq49)?;
    f.note("the separation angles differ from those of (42) for the same masses, as the text says (compare the tables)");
    Ok(f)
}

/// The identical-cylinder points I(k).
fn identical(cx: &Ctx) -> Vec<Point> {
    cx.points
        .iter()
        .filter(|p| p.name.starts_with("I("))
        .cloned()
        .collect()
}

pub fn eq50(cx: &mut Ctx) -> Result<Finding> {
    let mut f = Finding::default();
    let mut corr = Tally::default();
    for p in identical(cx) {
        let ths = cx.theta_s(&p, SR.0, SR.1)?;
        let k = X::q(PREC, &p.params.k2);
        let c = ths.cos();
        let at = format!("{} slip/roll at θs", p.name);
        let scale = 2 * (2 + &k);
        f.printed.add(
            "2[(2 + k)c − 1] − c(1 − c)²(1 + c)",
            &at,
            &sec3::eq50(&k, &c),
            &c.zero(),
            &scale,
        );
        corr.add(
            "(1 − k)c³ + 2k c² − (2 + k)(3 + k)c + 2(2 + k)",
            &at,
            &corrected::eq50(&k, &c),
            &c.zero(),
            &scale,
        );
        f.roots.push(RootRow {
            case: format!("{} slip/roll", p.name),
            printed: first_root_cos(|c| sec3::eq50(&k, c)),
            corrected: first_root_cos(|c| corrected::eq50(&k, c)),
            oracle: ths,
        });
    }
    f.corrected = Some((
        "(1 − k) cos³θs + 2k cos²θs − (2 + k)(3 + k) cos θs + 2(2 + k) = 0".into(),
        corr,
    ));
    f.note("from (47) with m1 = m2, k1 = k2 = k: K = (2 + k − c²)/2, θ̇² = 4(g/r)(1 − c)/(2 + k − c²), θ̈ from the energy; (49) then reduces to the cubic above (for k = 0 it is c³ − 6c + 4 = 0, the frictionless case of (43))");
    Ok(f)
}

pub fn eq52(cx: &mut Ctx) -> Result<Finding> {
    check(cx, rest(RS), |c, y| {
        let p = sec3::eq52(y);
        let (m, s) = (truth::momentum(Sys::SlipContact, y, QP1), &c.scales.angmom);
        vec![
            printed("= ∂T/∂φ̇1", p.clone(), &m, s),
            printed("= 0", p, &y.r1.zero(), s),
        ]
    })
}

pub fn fn11(cx: &mut Ctx) -> Result<Finding> {
    let half = Rational::from((1, 2));
    let mut pts: Vec<Point> = cx
        .random()
        .iter()
        .map(|p| with_k(p, &half, &half, &format!("{} k=1/2", p.name)))
        .collect();
    pts.push(cx.point("I(1/2)")?);
    let f = check(
        cx,
        |_| on_points(pts, SR),
        |c, y| {
            let sc = &c.scales.force / &y.r;
            vec![printed("= 0", sec3::fn11(y), &y.r1.zero(), &sc)]
        },
    )?;
    Ok(f.with_note(
        "random masses and radii with k1 = k2 = 1/2 (the relation needs no equal radii)",
    ))
}

pub fn fn12(cx: &mut Ctx) -> Result<Finding> {
    let f = check(
        cx,
        |cx| on_points(identical(cx), SR),
        |c, y| {
            let [pd, p1, p2] = sec3::fn12(y);
            let one = y.r1.n(1);
            vec![
                printed("φ̇1 = θ̇", pd, &y.phi1d, &c.scales.omega),
                printed("φ1 = θ", p1, &y.phi1, &one),
                printed("φ2 = φ1 − θ", p2, &y.phi2, &one),
                printed("φ2 = 0", y.r1.zero(), &y.phi2, &one),
            ]
        },
    )?;
    Ok(f.with_note("φ2 = 0 means cylinder 2 turns clockwise by θ, as does cylinder 1 (φ1 = θ) and the line of centres: one rigid body (sliding on the frictionless floor), until they separate"))
}

pub fn fn12_routh(cx: &mut Ctx) -> Result<Finding> {
    let f = check(
        cx,
        |cx| on_points(identical(cx), SR),
        |_, y| {
            vec![printed(
                "= 0 at every angle",
                sec3::fn12_routh(y),
                &y.r1.zero(),
                &y.g,
            )]
        },
    )?;
    Ok(f.with_note("Routh's relation holds at every sample angle, not only at separation: it is the energy relation (47) for identical cylinders, as the paper says, and cannot locate θs"))
}

/// θ̈ at rest at θ0 (both rolling), from the reduced dynamics.
fn thdd_at_rest(p: &Point, theta0: &Rational) -> Result<(X, X)> {
    let m = Ideal::new(
        p.params.clone(),
        Floor::Roll,
        Contact::Roll,
        Start {
            theta0: Exact::rational(theta0.clone()),
            thetadot0: Rational::new(),
            omega0: p.omega0.clone(),
        },
    )?;
    let red = Reduced::new(&m)?;
    let d = Dyn::new(&m, &red, PREC)?;
    let st = d.state(&Float::new(PREC));
    let gr = X::q(PREC, &Rational::from(&p.params.g / &p.params.r()));
    Ok((X(st.thetaddot), gr))
}

pub fn p_steady(cx: &mut Ctx) -> Result<Finding> {
    let mut f = Finding::default();
    let mut corr = Tally::default();
    for p in cx.general() {
        let (a, gr) = thdd_at_rest(&p, &p.theta0)?;
        let at = format!(
            "{} at rest at θ0 = {}",
            p.name,
            crate::exact::rational_text(&p.theta0)
        );
        f.printed
            .add("θ̈ = 0 at θ = θ0 ≠ 0", &at, &a, &a.zero(), &gr);
        let (b, gr) = thdd_at_rest(&p, &Rational::new())?;
        corr.add(
            "θ̈ = 0 at θ = 0",
            &format!("{} at rest at θ0 = 0", p.name),
            &b,
            &b.zero(),
            &gr,
        );
    }
    f.corrected = Some((
        "the only steady motion is θ ≡ 0 (cylinder 2 directly above cylinder 1), φ1 = ω0 t; at θ0 ≠ 0 the cylinders cannot stay at a fixed angle, since θ̈ = (g/r) sin θ0 / K(cos θ0) ≠ 0".into(),
        corr,
    ));
    f.note("the instability holds: near θ = 0, θ̈ ≈ (g/r) θ / K(1) with K(1) > 0");
    Ok(f)
}

/// The symbols of a rest case at angle θ (the motion continued past separation
/// if need be: the formula is the constrained motion's).
fn sym_theta(case: &Case, th: &X) -> Result<Sym> {
    let st = case.dynm.state(&th.0);
    case.sym(&st, &Float::new(PREC))
}

pub fn p_phi1(cx: &mut Ctx) -> Result<Finding> {
    let mut f = Finding::default();
    let mut pts: Vec<Point> = cx
        .general()
        .into_iter()
        .filter(|p| p.params.k2 < 1)
        .collect();
    if let Some(p) = pts.first().cloned() {
        let k = Rational::from((19, 20));
        pts.push(with_k(
            &p,
            &p.params.k1,
            &k,
            &format!("{} k2=19/20", p.name),
        ));
    }
    let pi = X(Float::with_val(PREC, rug::float::Constant::Pi));
    let below_pi = &pi - X::q(PREC, &Rational::from((1, 64)));
    for p in &pts {
        let case = cx.case(p, RR.0, RR.1, StartKind::Rest, false)?;
        let k2 = X::q(PREC, &p.params.k2);
        let star = first_root_below(&below_pi, |th| th.sin() - &k2 * th);
        let core = first_root_below(&below_pi, |th| match sym_theta(&case, th) {
            Ok(y) => y.phi1,
            Err(_) => th.zero(),
        });
        let ths = cx.theta_s(p, RR.0, RR.1)?;
        if let (Some(a), Some(b)) = (&star, &core) {
            f.printed.add("sin θ = k2 θ", &case.name, b, a, &a.n(1));
            f.note(format!(
                "{}: φ1 changes sign at θ = {} ({} separation at θs = {})",
                p.name,
                crate::numeric::decimal::to_sig(&a.0, 12),
                relative_to(a, &ths),
                crate::numeric::decimal::to_sig(&ths.0, 12)
            ));
        } else {
            f.printed
                .add_res("sin θ = k2 θ", &case.name, X::int(PREC, 1));
        }
    }
    f.note("the sign change is that of φ1 = −(A r/r1)(sin θ − k2 θ); whether it comes before separation depends on the parameters (the claim's 'if the cylinders remain in contact')");
    Ok(f)
}

pub fn p_phi1dot(cx: &mut Ctx) -> Result<Finding> {
    let mut f = Finding::default();
    let pts: Vec<Point> = cx
        .general()
        .into_iter()
        .filter(|p| p.params.k2 < 1)
        .collect();
    for p in &pts {
        let case = cx.case(p, RR.0, RR.1, StartKind::Rest, false)?;
        let k2 = X::q(PREC, &p.params.k2);
        let star = k2.acos();
        let core = first_root_below(&X::q(PREC, &Rational::from((3, 2))), |th| {
            match sym_theta(&case, th) {
                Ok(y) => y.phi1d,
                Err(_) => th.zero(),
            }
        });
        match core {
            Some(b) => f
                .printed
                .add("cos θ = k2", &case.name, &b, &star, &star.n(1)),
            None => f.printed.add_res("cos θ = k2", &case.name, X::int(PREC, 1)),
        }
        let sep = cx.separation(p, RR.0, RR.1)?;
        let from_oracle = sep.extra.iter().find(|v| v.name == "theta_phi1dot_zero");
        let ths = cx.theta_s(p, RR.0, RR.1)?;
        f.note(format!(
            "{}: cos θ = k2 at θ = {} ({} separation at {}; oracle: {})",
            p.name,
            crate::numeric::decimal::to_sig(&star.0, 12),
            relative_to(&star, &ths),
            crate::numeric::decimal::to_sig(&ths.0, 12),
            from_oracle
                .map(|v| format!(
                    "theta_phi1dot_zero = {}",
                    crate::numeric::decimal::to_sig(&v.value, 12)
                ))
                .unwrap_or_else(|| "no sign change before separation".into())
        ));
    }
    f.note("the text writes φ̇ for φ̇1");
    Ok(f)
}

/// "before", "at" or "after" separation.
fn relative_to(a: &X, ths: &X) -> &'static str {
    if (a - ths).abs() <= super::finding::hold_tol() * ths {
        "at"
    } else if a < ths {
        "before"
    } else {
        "after"
    }
}

/// A bobbin point on which φ2 shares θ's sign at small times: A r (k2 − 1) > r1.
fn bobbin_phi2_point() -> Point {
    let q = |n, d| Rational::from((n, d));
    Point {
        name: "B".into(),
        params: Params {
            m1: q(1, 2),
            m2: q(1, 1),
            r1: q(1, 4),
            r2: q(2, 1),
            k1: q(1, 2),
            k2: q(3, 1),
            g: q(981, 100),
        },
        theta0: q(1, 10),
        thetadot0: q(1, 10),
        omega0: q(1, 2),
        random: false,
    }
}

pub fn p_bobbin(cx: &mut Ctx) -> Result<Finding> {
    let mut f = Finding::default();
    let mut pts: Vec<Point> = cx
        .general()
        .into_iter()
        .filter(|p| p.params.k2 > 1)
        .collect();
    pts.push(bobbin_phi2_point());
    pts.push(cx.point("I(3/2)")?);
    for p in &pts {
        let case = cx.case(p, RR.0, RR.1, StartKind::Rest, false)?;
        let mut ys = case.syms.clone();
        ys.push(sym_theta(&case, &X(Float::with_val(PREC, 1u32) >> 20))?);
        for y in &ys {
            let bad = (&y.phi1 * &y.th).is_neg() || (&y.phi1d * &y.thd).is_neg();
            f.printed.add_res(
                "sign φ1 = sign θ and sign φ̇1 = sign θ̇ (0: at every sample)",
                &case.name,
                X::int(PREC, if bad { 1 } else { 0 }),
            );
        }
        let sep = cx.separation(p, RR.0, RR.1)?;
        let kept = sep
            .notes
            .iter()
            .filter(|n| n.contains("keeps its sign"))
            .count();
        f.note(format!(
            "{} (k2 = {}): the oracle's scan to separation finds {}",
            p.name,
            crate::exact::rational_text(&p.params.k2),
            if kept == 2 {
                "no sign change of φ̇1 or φ1"
            } else {
                "a sign change of φ̇1 or φ1"
            }
        ));
    }
    f.note("from rest: φ̇1 = (A r/r1)(k2 − cos θ) θ̇ and φ1 = (A r/r1)(k2 θ − sin θ) are positive for θ > 0 when k2 > 1");
    Ok(f)
}

pub fn p_momentum(cx: &mut Ctx) -> Result<Finding> {
    let mut f = Finding::default();
    let mut pts = cx.general();
    pts.push(bobbin_phi2_point());
    for p in &pts {
        let case = cx.case(p, RR.0, RR.1, StartKind::Rest, false)?;
        for y in &case.syms {
            let px = truth::px(y);
            f.printed.add_res(
                "P_x > 0 (0: at every sample)",
                &case.name,
                X::int(PREC, if px.is_neg() || px.0.is_zero() { 1 } else { 0 }),
            );
        }
    }
    f.note("true for every k2, not only k2 > 1: P_x = m2 r θ̇ [cos θ − (m1 + m2)(cos θ − k2)/((1 + k1) m1 + (1 + k2) m2)] > 0 while cos θ ≥ 0");
    Ok(f)
}

pub fn p_phi2(cx: &mut Ctx) -> Result<Finding> {
    let mut f = Finding::default();
    let mut pts = cx.general();
    pts.push(bobbin_phi2_point());
    let tiny = X(Float::with_val(PREC, 1u32) >> 20);
    let mut bobbin_same = Vec::new();
    let mut bobbin_opposite = Vec::new();
    for p in &pts {
        let case = cx.case(p, RR.0, RR.1, StartKind::Rest, false)?;
        let y = sym_theta(&case, &tiny)?;
        if p.params.k2 < 1 {
            let ok = y.phi1.is_neg() && y.phi2.is_neg();
            f.printed.add_res(
                "k2 < 1: φ1, φ2 both opposite to θ (0: yes)",
                &case.name,
                X::int(PREC, if ok { 0 } else { 1 }),
            );
        } else if y.phi2.is_neg() {
            bobbin_opposite.push(p.name.clone());
        } else {
            bobbin_same.push(p.name.clone());
        }
    }
    let subset = !bobbin_same.is_empty() && !bobbin_opposite.is_empty();
    f.printed.add_res(
        "k2 > 1: φ2 shares θ's sign for some parameters, not all (0: yes)",
        "bobbins",
        X::int(PREC, if subset { 0 } else { 1 }),
    );
    f.note(format!(
        "at θ = 2⁻²⁰ from rest; k2 > 1 with φ2 of θ's sign: {}; of the opposite sign: {} (the condition is A r (k2 − 1) > r1)",
        bobbin_same.join(", "),
        bobbin_opposite.join(", ")
    ));
    Ok(f)
}

pub fn p_fixed_slip(cx: &mut Ctx) -> Result<Finding> {
    let mut f = Finding::default();
    let two_thirds = X::q(PREC, &Rational::from((2, 3)));
    for p in cx.random() {
        let ths = cx.theta_s(&p, Floor::Fixed, Contact::Slip)?;
        f.printed.add(
            "cos θs = 2/3",
            &format!("{} fixed/slip", p.name),
            &two_thirds,
            &ths.cos(),
            &two_thirds.n(1),
        );
        f.roots.push(RootRow {
            case: format!("{} fixed/slip", p.name),
            printed: Some(two_thirds.acos()),
            corrected: None,
            oracle: ths,
        });
    }
    Ok(f)
}

pub fn p_fixed_roll(cx: &mut Ctx) -> Result<Finding> {
    let mut f = Finding::default();
    for p in fixed_points(cx) {
        let ths = cx.theta_s(&p, Floor::Fixed, Contact::Roll)?;
        let c = sec2::eq36(&X::q(PREC, &p.params.k2));
        f.printed.add(
            "cos θs = 2/(3 + k2)",
            &format!("{} fixed/roll", p.name),
            &c,
            &ths.cos(),
            &c.n(1),
        );
    }
    f.note("the same statement as eq. (36), repeated at the end of sec. 3.2");
    Ok(f)
}

calls! {
    eq38 => kinetic(SS, sec3::eq38);
    eq40 => energy_zero(SS, sec3::eq40);
    eq41 => geff(SS, |y| sec3::eq41(y).to_vec(), &["−ẍ1", "(m2 r/(m1 + m2))(…)"]);
    eq42 => sep_form(SS, sec3::eq42);
    eq44 => kinetic(SR, sec3::eq44);
    eq47 => energy_zero(SR, sec3::eq47);
    eq48 => geff(SR, |y| sec3::eq48(y).to_vec(), &["−ẍ1", "(m2 r/(m1 + m2))(…)"]);
    eq51 => kinetic(RS, sec3::eq51);
    eq53 => energy_zero(RS, sec3::eq53);
    eq54 => geff(RS, |y| sec3::eq54(y).to_vec(), &["−ẍ1", "−r1 φ̈1", "(m2 r/((1 + k1) m1 + m2))(…)"]);
    eq55 => sep_form(RS, sec3::eq55);
}
