//! The mode decision: at the start and at every event, which continuations
//! of the motion are consistent with the contact laws.

use super::ctx::{lam, normal_row, tangent, Ctx};
use super::mode::{Branch, Mode, State};
use crate::error::{Error, Result};
use crate::integrate::solve::Sample;
use crate::mechanics::system::{self as sy, Row, System, Tangent};
use crate::model::{Law, Which};
use crate::numeric::decimal::to_sig as sig;
use rug::Float;

/// Why a candidate mode is not consistent (None: it is).
pub fn inconsistency(ctx: &Ctx, mode: Mode, q: &[Float], v: &[Float]) -> Result<Option<String>> {
    inconsistency_at(ctx, mode, q, v, false)
}

/// [`inconsistency`], tested over the Euler steps of ε = 2^−(p/3)·T, or
/// (`short`) of ε = 2^−(p/2 − 8)·T: as short as the test's second-order
/// term allows (ε² s̈ still 2^16 times the rounding of a rate).
fn inconsistency_at(
    ctx: &Ctx,
    mode: Mode,
    q: &[Float],
    v: &[Float],
    short: bool,
) -> Result<Option<String>> {
    let mut sys = ctx.system(mode)?;
    let p = sys.prec;
    let acc = match sys.accel(q, v) {
        Ok(a) => a,
        Err(_) => return Ok(Some("its constraint system is singular".into())),
    };
    // just after: one Euler step of ε = 2^−(p/3)·T along the mode's flow
    let shift = if short {
        p as i32 / 2 - 8
    } else {
        p as i32 / 3
    };
    let eps = Float::with_val(p, &ctx.ts) >> shift;
    let q1: Vec<Float> = q
        .iter()
        .zip(v)
        .map(|(x, d)| Float::with_val(p, x + Float::with_val(p, d * &eps)))
        .collect();
    let v1: Vec<Float> = v
        .iter()
        .zip(&acc.qdd)
        .map(|(x, d)| Float::with_val(p, x + Float::with_val(p, d * &eps)))
        .collect();
    let a1 = match sys.accel(&q1, &v1) {
        Ok(a) => a,
        Err(_) => return Ok(Some("its constraint system is singular".into())),
    };
    // a second step, for slip speeds that leave 0 only at second order (at
    // a slip onset with μs = μk the sliding force equals the sticking one,
    // so ṡ = 0 there and the sign of s̈ decides): s(2ε) ≈ s + 2ε ṡ + ε² s̈
    let v2: Vec<Float> = v1
        .iter()
        .zip(&a1.qdd)
        .map(|(x, d)| Float::with_val(p, x + Float::with_val(p, d * &eps)))
        .collect();
    let s1 = Sample {
        t: Float::new(p),
        q: q1.clone(),
        v: v1.clone(),
        qdd: a1.qdd,
        lambda: a1.lambda,
        work: Float::new(p),
        power: Float::new(p),
        trig: Vec::new(),
        energy: None,
    };
    let n12 = lam(&sys, &s1, Row::Normal(0));
    if !n12.is_sign_positive() || n12.is_zero() {
        return Ok(Some(format!("N12 would be {} <= 0", sig(&n12, 4))));
    }
    if !ctx.held {
        let n1 = lam(&sys, &s1, Row::FloorNormal);
        if !n1.is_sign_positive() || n1.is_zero() {
            return Ok(Some(format!("N1 would be {} <= 0", sig(&n1, 4))));
        }
    }
    for (w, st) in [(Which::Floor, mode.floor), (Which::Contact, mode.contact)] {
        match (st, ctx.law(w)) {
            (State::Stick, Law::Coulomb { .. }) => {
                // a contact can stick only where it does not slide
                let s0 = sys.slip_speed(tangent(w), q, v);
                let vscale = Float::with_val(p, &ctx.base_r / &ctx.ts);
                if Float::with_val(p, s0.abs_ref()) > vscale * &ctx.rel_tiny {
                    return Ok(Some(format!(
                        "the {} slides (slip speed {}): it cannot stick",
                        w.name(),
                        sig(&s0, 4)
                    )));
                }
                let n = lam(&sys, &s1, normal_row(w));
                let f = ctx.tangential(&sys, mode, w, &s1);
                let mu = ctx.mu_s[w as usize]
                    .clone()
                    .unwrap_or_else(|| Float::new(p));
                let room = Float::with_val(p, &mu * &n) - Float::with_val(p, f.abs_ref());
                if room.is_sign_negative() {
                    return Ok(Some(format!(
                        "sticking at the {} would need |F|/N = {} > mu_s",
                        w.name(),
                        sig(&(Float::with_val(p, f.abs_ref()) / &n), 7)
                    )));
                }
            }
            (State::Slip(sg), Law::Coulomb { .. }) if sg != 0 => {
                let s = sys.slip_speed(tangent(w), &q1, &v2);
                if s.is_zero() || s.is_sign_negative() != (sg < 0) {
                    return Ok(Some(format!(
                        "slipping {} at the {} would need a slip speed of that sign (it would be {})",
                        if sg > 0 { "forwards" } else { "backwards" },
                        w.name(),
                        sig(&s, 4)
                    )));
                }
            }
            _ => {}
        }
    }
    Ok(None)
}

/// A disparity of the parameters beyond the range the README says is
/// answered under every law that makes part of the motion fast: an upper
/// cylinder more than 10^12 times
/// heavier than the lower one (a light upper cylinder is the fixed lower
/// one's limit, and slow), or a moment of inertia below 10^-12 of m r²
/// (k1, k2). There the mode test's Euler steps do not resolve the fast
/// motion. Or a common rolling ω0 whose speed ω0 r1 exceeds the motion's own
/// by more than a third of the working precision's bits: the slip speeds
/// the test reads cancel there.
fn disparity(ctx: &Ctx) -> Option<(String, bool)> {
    let pr = ctx.model.params();
    let limit = rug::Rational::from(rug::Integer::from(rug::Integer::u_pow_u(10, 12)));
    let r = rug::Rational::from(&pr.m2 / &pr.m1);
    if r > limit {
        return Some((
            format!(
                "the masses differ by a factor {}",
                crate::numeric::decimal::short_near(&Float::with_val(64, &r))
            ),
            true,
        ));
    }
    for (name, k) in [("k1", &pr.k1), ("k2", &pr.k2)] {
        if *k > 0 && rug::Rational::from(k.recip_ref()) > limit {
            return Some((
                format!(
                    "{name} = {} leaves a spin almost without inertia",
                    crate::numeric::decimal::short_near(&Float::with_val(64, k))
                ),
                true,
            ));
        }
    }
    // a common rolling ω0 moves every body alike, but its terms are in the
    // rates the slip speeds are differences of: ω0 r1 against the motion's
    // own speed sqrt(g r) costs log2 of their ratio in bits there
    let w0 = &ctx.model.start().omega0;
    if *w0 != 0 {
        let p = 64;
        let speed = Float::with_val(p, w0).abs() * Float::with_val(p, &pr.r1);
        let rsum = rug::Rational::from(&pr.r1 + &pr.r2);
        let own = (Float::with_val(p, &pr.g) * Float::with_val(p, &rsum)).sqrt();
        let ratio = speed / own;
        if ratio.get_exp().is_some_and(|e| e > (ctx.p / 3) as i32) {
            return Some((
                format!(
                    "the common rolling rate omega0 = {} makes the bodies' speeds {} times the \
                     motion's own (sqrt(g (r1 + r2))), and the slip speeds, their differences, \
                     lose that much at this precision (a higher --digits keeps more)",
                    crate::numeric::decimal::short_near(&Float::with_val(64, w0)),
                    crate::numeric::decimal::short_near(&ratio)
                ),
                false,
            ));
        }
    }
    None
}

/// What a failed mode decision says of the rigid-body model: `model_says`
/// (a Painlevé-type property of the model), or, beyond the tested range of
/// the parameters ([`disparity`]), that whether the model `question` is not
/// decided — the candidates are tested by Euler steps far longer than the
/// fast part of such a motion takes to change.
fn verdict(ctx: &Ctx, question: &str, model_says: &str) -> String {
    match disparity(ctx) {
        Some((cause, true)) => format!(
            "{cause}, and the motion it makes fast is too fast for the test of the candidates; \
             whether the rigid-body model {question} is not decided"
        ),
        Some((cause, false)) => {
            format!("{cause}; whether the rigid-body model {question} is not decided")
        }
        None => model_says.to_string(),
    }
}

/// The relative normal acceleration r̈ of the centres if the contact
/// between the cylinders were open at (q, q̇): cylinder 2 falls freely,
/// cylinder 1 moves under its floor law alone.
pub fn free_normal_accel(ctx: &Ctx, sys: &System, q: &[Float], v: &[Float]) -> Float {
    let p = sys.prec;
    let th = &q[sy::th(0)];
    let (sn, cs) = th.clone().sin_cos(Float::new(p));
    let r = &q[sy::rr(0)];
    let thd = &v[sy::th(0)];
    let s1 = sys.slip_speed(Tangent::Floor, q, v);
    let snap = Float::with_val(p, ctx.ts.recip_ref()) * &ctx.base_r * &ctx.rel_tiny;
    let sticking = Float::with_val(p, s1.abs_ref()) <= snap;
    let a1x = ctx.floor_accel(sys, q, v, sticking);
    // r̈ = n·(a2 − a1) + r θ̇², a2 = (0, −g)
    let mut rdd = Float::with_val(p, thd.square_ref()) * r;
    rdd -= Float::with_val(p, &sys.g * &cs);
    rdd -= Float::with_val(p, &sn * &a1x);
    rdd
}

/// The continuation chosen at (q, q̇).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Choice {
    /// The mode with the contact closed, or None: the contact opens.
    pub mode: Option<Mode>,
    /// Both a closed mode and the contact opening are consistent here: a
    /// branch point of the rigid-body model (the chosen continuation
    /// follows the requested branch).
    pub branch_point: bool,
    /// The consistent closed mode, whichever continuation is chosen.
    pub closed: Option<Mode>,
}

/// The consistent continuation at (q, q̇): every combination of the
/// contacts' states is tested just after the present state, and the
/// contact between the cylinders opening. A contact at rest on its
/// partner sticks if it can (Coulomb's law); where both a closed mode and
/// opening are consistent (a branch point), `branch` decides.
///
/// Errors: none consistent (a Painlevé-type inconsistency), or more than
/// one closed mode (Painlevé-type non-uniqueness), with the reasons; beyond
/// the tested range of the parameters (`disparity`) either is said to be
/// undecided rather than a property of the rigid-body model.
pub fn decide(ctx: &Ctx, q: &[Float], v: &[Float], t: &Float, branch: &Branch) -> Result<Choice> {
    decide_with(ctx, q, v, t, branch, None)
}

/// [`decide`], with whether the contact opening is consistent given
/// (`opens`: at the start, the closed motion's exact sign of the free
/// normal acceleration just after it, where the test's own reading is a
/// rounding of 0: a start exactly where the free motion parts, θ0 = π/3
/// with θ̇0 = 1/2, was decided one way or the other by the digits asked).
///
/// Errors: as [`decide`].
pub fn decide_with(
    ctx: &Ctx,
    q: &[Float],
    v: &[Float],
    t: &Float,
    branch: &Branch,
    opens: Option<bool>,
) -> Result<Choice> {
    let mut ok = Vec::new();
    let mut why = Vec::new();
    // the candidates over the test's usual steps, and where none passes,
    // over the shortest it allows: two events closer than the usual step
    // (a heavy upper cylinder on a light one: the floor starts to slip
    // 6·10^-13 of the time unit after the contact at m2 = 10^13 m1, 6·10^-14
    // at 10^14) made every candidate fail, each seeing the later event too
    for short in [false, true] {
        ok.clear();
        why.clear();
        for f in ctx.candidates(Which::Floor) {
            for c in ctx.candidates(Which::Contact) {
                let m = Mode {
                    floor: f,
                    contact: c,
                };
                match inconsistency_at(ctx, m, q, v, short)? {
                    None => ok.push(m),
                    Some(r) => why.push(format!("{}: {r}", m.tag())),
                }
            }
        }
        if !ok.is_empty() {
            break;
        }
    }
    // the contact opening: consistent when the free motion separates
    let sys = ctx.system(ok.first().copied().unwrap_or(Mode {
        floor: ctx.candidates(Which::Floor)[0],
        contact: State::Stick,
    }))?;
    let rdd = free_normal_accel(ctx, &sys, q, v);
    let opens = opens.unwrap_or(rdd.is_sign_positive() && !rdd.is_zero());
    let theta = q[sy::th(0)].to_f64();
    let at = format!("t = {}, theta = {theta:.12}", sig(t, 12));
    // Coulomb's law: a contact at rest relative to its partner sticks if the
    // force that holds it is within μs N; sliding from rest is the
    // continuation only where sticking is not (this settles the choice
    // between sticking and kinetic sliding when μk < μs)
    if ok.len() > 1 {
        for w in [Which::Floor, Which::Contact] {
            if ok.iter().any(|m| m.of(w) == State::Stick) {
                ok.retain(|m| m.of(w) == State::Stick);
            }
        }
    }
    match (ok.len(), opens) {
        (1, false) => Ok(Choice {
            mode: Some(ok[0]),
            branch_point: false,
            closed: Some(ok[0]),
        }),
        (0, true) => Ok(Choice {
            mode: None,
            branch_point: false,
            closed: None,
        }),
        (1, true) => Ok(Choice {
            mode: match branch {
                Branch::Part => None,
                Branch::Stay | Branch::PartAt(_) => Some(ok[0]),
            },
            branch_point: true,
            closed: Some(ok[0]),
        }),
        (0, false) => Err(Error::NotConverged {
            quantity: "mode".into(),
            requested: 0,
            reached: if disparity(ctx).is_some() {
                format!("no candidate passed the test at {at}")
            } else {
                format!("no consistent continuation at {at}")
            },
            // the verdict first: a one-line message shortens the list of
            // the candidates' reasons, not the conclusion
            detail: format!(
                "{}; every candidate fails ({}; the contact cannot open: free relative normal \
                 acceleration {})",
                verdict(
                    ctx,
                    "has a continuation here",
                    "a Painlevé-type inconsistency of the rigid-body model"
                ),
                why.join("; "),
                sig(&rdd, 4)
            ),
        }),
        (n, o) => Err(Error::NotConverged {
            quantity: "mode".into(),
            requested: 0,
            reached: format!("{} consistent continuations at {at}", n + usize::from(o)),
            detail: format!(
                "{}{}: {}",
                ok.iter().map(|m| m.tag()).collect::<Vec<_>>().join(", "),
                if o { ", contact opening" } else { "" },
                verdict(
                    ctx,
                    "decides here",
                    "the rigid-body model does not decide (Painlevé-type non-uniqueness)"
                )
            ),
        }),
    }
}

/// Every continuation consistent at a branch point besides staying in
/// `mode`: `part` (the contact opening, consistent there by definition)
/// and any other closed mode that is consistent too (sliding from rest
/// where sticking is still consistent: with μs = μk this happens only
/// together with parting).
///
/// Errors: a singular constraint system of a candidate (reported as
/// inconsistent, not as an error) never; a failed KKT evaluation.
pub fn alternatives(ctx: &Ctx, mode: Mode, q: &[Float], v: &[Float]) -> Result<Vec<String>> {
    let mut out = vec!["part".to_string()];
    for f in ctx.candidates(Which::Floor) {
        for c in ctx.candidates(Which::Contact) {
            let m = Mode {
                floor: f,
                contact: c,
            };
            if m != mode && inconsistency(ctx, m, q, v)?.is_none() {
                out.push(m.tag());
            }
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::Exact;
    use crate::model::{Model, Params, Start};

    /// The main case (μ = 0.3, rest at θ0 = 1/10) with g = 10^k.
    fn main_with_g(k: i32) -> Model {
        let n = rug::Integer::from(rug::Integer::u_pow_u(10, k.unsigned_abs()));
        let mut p = Params::identical_solid();
        p.g = if k >= 0 {
            rug::Rational::from(n)
        } else {
            rug::Rational::from((1, n))
        };
        let mu = || Law::parse_mu("mu", "0.3").unwrap();
        let start = Start::rest(Exact::parse("theta0", "1/10", false).unwrap());
        Model::new(p, mu(), mu(), start).unwrap()
    }

    /// Why a mode fails, in any units: at the start of the main case,
    /// sliding backwards at the contact would need a slip speed of that
    /// sign, and the message quotes the speed it would have. At g = 10^-1000
    /// (a speed of 1.4·10^-516, 0 in f64: the message read "(it would be
    /// 0.000e0)", contradicting itself) its digits are those at g = 1, the
    /// power of ten moved by 500.
    #[test]
    fn a_failing_mode_quotes_its_numbers_in_any_units() {
        let why = |k: i32| {
            let ctx = Ctx::new(&main_with_g(k), 120).unwrap();
            let stick = Mode {
                floor: State::Stick,
                contact: State::Stick,
            };
            let (q, v) = ctx.system(stick).unwrap().initial_state(&ctx.base).unwrap();
            let back = Mode {
                floor: State::Stick,
                contact: State::Slip(-1),
            };
            inconsistency(&ctx, back, &q, &v)
                .unwrap()
                .expect("the mode fails")
        };
        let (unit, tiny) = (why(0), why(-1000));
        let number = |s: &str| -> String {
            let at = s.find("it would be ").expect(s) + "it would be ".len();
            s[at..].trim_end_matches(')').to_string()
        };
        let (a, b) = (number(&unit), number(&tiny));
        let (ma, ea) = a.split_once('e').expect(&a);
        let (mb, eb) = b.split_once('e').expect(&b);
        assert_eq!(ma, mb, "{unit} / {tiny}");
        assert_eq!(
            ea.parse::<i64>().unwrap() - 500,
            eb.parse::<i64>().unwrap(),
            "{unit} / {tiny}"
        );
    }
}
