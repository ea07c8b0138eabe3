//! What `separation` finds besides θs and t_s: N1 along the motion (its
//! sign, its minimum, the friction the floor needs) from polynomials in
//! cos θ, the largest friction each rolling contact needs and where, the
//! angles where φ̇1 and φ1 change sign, F21 at separation, and the angles
//! where rolling fails for a given μ; each verified by the precision ladder.

use super::{At, Oracle};
use crate::error::Result;
use crate::integrate::energy::engine::Engine;
use crate::integrate::energy::{SCAN_PREC, SCAN_STEPS};
use crate::model::{Contact, Floor};
use crate::numeric::verify::{ladder, Estimate, Verified};
use rug::Float;

/// The note where the masses' ratio is beyond the bits the comparison of N1
/// along the motion is given ([`Oracle::findings_prec`]).
pub(crate) const NOT_COMPARED: &str = "N1 along the motion (its sign, its minimum) and the most \
     friction a rolling contact needs are not computed: the masses differ by more than 2^8192, \
     beyond the bits their comparison along the motion is given";

impl Oracle {
    /// The precision at which N1 and the friction needed are compared along
    /// the motion up to the angle `end` (working frame): the scan's 96 bits,
    /// the bits of the masses' ratio where it is extreme
    /// ([`crate::integrate::energy::mass_spread_bits`]), and four times the
    /// binary order of an `end` below 2^-8 (the polynomials are in c = cos θ,
    /// whose distance from 1 is θ²/2, and the extremum's condition E(c)
    /// squares it again: under θs = 10^-7 the candidates were compared, and
    /// a root refined, in the last bits of c; twice was not enough there). `None` where the
    /// masses' ratio is beyond the bits given to it (the findings that need
    /// the comparison are not made, and a note says so: [`NOT_COMPARED`]).
    pub(crate) fn findings_prec(&self, end: &Float) -> Option<u32> {
        // (below 2^-8 only: an ordinary motion keeps its bits)
        let angle = match end.get_exp() {
            Some(e) if e <= -8 => {
                (4 * e.unsigned_abs()).min(crate::integrate::energy::MAX_SPREAD_BITS)
            }
            _ => 0,
        };
        crate::integrate::energy::mass_spread_bits(self.route.work.params())
            .map(|b| SCAN_PREC + b + angle)
    }

    /// N1 on [θ0, θs] from N1·K², a polynomial in c = cos θ (K > 0): its
    /// real roots on [cos θs, cos θ0] are isolated (by the monotone pieces
    /// between the roots of its derivatives, [`crate::numeric::poly`]), so
    /// "N1 > 0 up to separation" is a statement about every angle, not about
    /// scan points. Its minimum is at an end or at a root of
    /// D = B'K − 2BK' (B = N1·K²); the largest friction the floor needs,
    /// |F1|/N1 = sin θ·|A|/B (A = F1·K²/sin θ), at an end or a root of
    /// E = cAB − (1 − c²)(A'B − AB'). Each is verified like θs: the root
    /// refined at both precisions, θ = acos c, the value at θ.
    fn n1_findings(
        &mut self,
        ds_scan: &Float,
        extra: &mut Vec<Verified>,
        notes: &mut Vec<String>,
    ) -> Result<()> {
        use crate::mechanics::dynamics::{HPoly, N12Poly};
        use crate::numeric::poly;
        let fp = self.route.force_polys();
        let q = |v: i64| rug::Rational::from(v);
        let k = HPoly::constant(&fp.k);
        let b = HPoly::linear(&fp.n1);
        let d = b.deriv().mul(&k).add_scaled(&b.mul(&k.deriv()), &q(-2));

        let th_s_scan = Float::with_val(
            SCAN_PREC,
            self.route.work.start().theta0.to_float(SCAN_PREC) + ds_scan,
        );
        let Some(p) = self.findings_prec(&th_s_scan) else {
            notes.push(NOT_COMPARED.to_string());
            return Ok(());
        };
        let (c0, a_h) = {
            let eng = self.route.engine(p)?;
            (eng.dynm.c0.clone(), N12Poly::a_h(&eng.dynm))
        };
        // θs to the bits compared (the scan's value where they are the scan's)
        let ds = if p == SCAN_PREC {
            ds_scan.clone()
        } else {
            self.route.delta_s(p)?.0
        };
        let th_s = Float::with_val(p, self.route.work.start().theta0.to_float(p) + &ds);
        let cs = Float::with_val(p, th_s.cos_ref());
        if cs >= c0 {
            return Ok(());
        }
        let roots_in = |hp: &HPoly| -> Vec<Float> {
            poly::sign_change_roots(&hp.at(&a_h, p), &cs, &c0)
                .into_iter()
                .filter(|c| *c > cs && *c < c0)
                .collect()
        };
        let eval = |hp: &HPoly, c: &Float| -> Float {
            let mut v = Float::new(p);
            poly::horner(&hp.at(&a_h, p), c, &mut v);
            v
        };
        // the first root of N1 in θ: the largest c
        if let Some(cz) = roots_in(&b).into_iter().next_back() {
            let v = self.verify_at("theta_N1_zero", None, &At::Root(cz, b.clone()), p)?;
            notes.push(format!(
                "N1 vanishes at theta = {} before separation: cylinder 1 would leave the floor there, \
                 and the motion after that angle (including theta_s) is not the model's",
                v[0].text
            ));
            extra.extend(v);
            return Ok(());
        }
        notes.push(
            "N1 > 0 at every angle from theta0 to theta_s (N1 K^2, a polynomial in cos theta, \
             has no root there): cylinder 1 stays on the floor"
                .to_string(),
        );
        // candidates: the ends and the interior extrema
        let pick = |cands: Vec<At>, f: &dyn Fn(&Float) -> Float, max: bool| -> At {
            let mut best: Option<(Float, At)> = None;
            for at in cands {
                let c = match &at {
                    At::Start => c0.clone(),
                    At::Separation | At::Angle(_) => cs.clone(),
                    At::Root(c, _) => c.clone(),
                };
                let v = f(&c);
                let better = match &best {
                    None => true,
                    Some((bv, _)) => {
                        if max {
                            v > *bv
                        } else {
                            v < *bv
                        }
                    }
                };
                if better {
                    best = Some((v, at));
                }
            }
            best.map(|b| b.1).unwrap_or(At::Start)
        };
        let kq = |c: &Float| eval(&k, c);
        let n1_of = |c: &Float| -> Float {
            let kk = kq(c);
            Float::with_val(p, eval(&b, c) / Float::with_val(p, kk.square_ref()))
        };
        let mut cands = vec![At::Start, At::Separation];
        cands.extend(roots_in(&d).into_iter().map(|c| At::Root(c, d.clone())));
        let at_min = pick(cands, &n1_of, false);
        let v = self.verify_at("theta_N1_min", Some("N1_min"), &at_min, p)?;
        extra.extend(v);
        if self.route.work.floor() != Floor::Slip {
            extra.extend(self.needed_max(false, At::Separation, &cs, p)?);
        }
        Ok(())
    }

    /// The largest friction a rolling contact needs over [θ0, end] — the
    /// floor (|F1|/N1) or, with `contact_side`, the contact between the
    /// cylinders (|F21|/N12) — and where: the ratio is sin θ·|A|/B with A, B
    /// polynomials in c = cos θ ([`crate::mechanics::dynamics::ForcePolys`],
    /// B > 0 inside the motion), so its maximum is at an end or at a root of
    /// E = cAB − (1 − c²)(A'B − AB') on [c_end, cos θ0]; the candidates are
    /// compared at [`Oracle::findings_prec`] and the winner verified
    /// ([`Oracle::verify_at`]). `c_end` is cos of the end angle at that
    /// precision, `p`.
    pub(super) fn needed_max(
        &mut self,
        contact_side: bool,
        end: At,
        c_end: &Float,
        p: u32,
    ) -> Result<Vec<Verified>> {
        use crate::mechanics::dynamics::{HPoly, N12Poly};
        use crate::numeric::poly;
        let fp = self.route.force_polys();
        let q = |v: i64| rug::Rational::from(v);
        let (a, b) = if contact_side {
            let np = self
                .route
                .caches
                .n12_poly
                .get_or_insert_with(|| N12Poly::new(&self.route.red, self.route.work.params()))
                .clone();
            let m2 = self.route.work.params().m2.clone();
            // N12·K² = m2 · (N12·K²/m2)
            let b = HPoly::default().add_scaled(&HPoly::linear(&(np.base, np.per_h)), &m2);
            (HPoly::linear(&fp.f21), b)
        } else {
            (HPoly::linear(&fp.f1), HPoly::linear(&fp.n1))
        };
        let cpoly = HPoly::constant(&[q(0), q(1)]);
        let one_m_c2 = HPoly::constant(&[q(1), q(0), q(-1)]);
        let apb = a.deriv().mul(&b).add_scaled(&a.mul(&b.deriv()), &q(-1));
        let e = cpoly
            .mul(&a)
            .mul(&b)
            .add_scaled(&one_m_c2.mul(&apb), &q(-1));
        let (c0, a_h) = {
            let eng = self.route.engine(p)?;
            (eng.dynm.c0.clone(), N12Poly::a_h(&eng.dynm))
        };
        let (theta_name, value_name) = if contact_side {
            ("theta_mu_contact_max", "mu_contact_max")
        } else {
            ("theta_mu_floor_max", "mu_floor_max")
        };
        let eval = |hp: &HPoly, c: &Float| -> Float {
            let mut v = Float::new(p);
            poly::horner(&hp.at(&a_h, p), c, &mut v);
            v
        };
        let ratio = |c: &Float| -> Float {
            let s = Float::with_val(p, 1u32 - Float::with_val(p, c.square_ref())).sqrt();
            Float::with_val(p, s * eval(&a, c) / eval(&b, c)).abs()
        };
        let mut best = (ratio(&c0), At::Start);
        if *c_end < c0 {
            let v = ratio(c_end);
            if v > best.0 {
                best = (v, end);
            }
            for c in poly::sign_change_roots(&e.at(&a_h, p), c_end, &c0) {
                if c > *c_end && c < c0 {
                    let v = ratio(&c);
                    if v > best.0 {
                        best = (v, At::Root(c, e.clone()));
                    }
                }
            }
        }
        self.verify_at(theta_name, Some(value_name), &best.1, p)
    }

    /// The angle `at` (named `theta_name`) and, with `value`, the quantity
    /// there (`N1_min`: N1; `mu_floor_max`: |F1|/N1), verified at two
    /// precisions. The value's error includes its change across the angle's
    /// error bound.
    fn verify_at(
        &mut self,
        theta_name: &str,
        value: Option<&str>,
        at: &At,
        p: u32,
    ) -> Result<Vec<Verified>> {
        use crate::mechanics::dynamics::N12Poly;
        let mut names = vec![theta_name];
        if let Some(v) = value {
            names.push(v);
        }
        // each run with the comparison's bits beyond the scan's
        // ([`Oracle::findings_prec`], `p`): near θs under a lower cylinder
        // 10^60 times lighter, N1 is of the lighter scale in sums of the
        // heavier, and the extremum ~(m1/m2)^(1/2) from θs; under a tiny θs
        // the root's c lies in the last bits
        let spread = p.saturating_sub(SCAN_PREC);
        ladder(self.digits, &names, |p_run| {
            let p = p_run + spread;
            let th0 = self.route.work.start().theta0.to_float(p);
            let (delta, derr) = match at {
                At::Start => (Float::new(p), Float::new(p)),
                At::Separation => self.route.delta_s(p)?,
                At::Angle(th) => (
                    self.route.delta_of("theta", th, p, self.digits)?,
                    Float::new(p),
                ),
                At::Root(c_iso, hp) => {
                    let a_h = N12Poly::a_h(&self.route.engine(p)?.dynm);
                    let coef = hp.at(&a_h, p + 16);
                    let (c, eps) = crate::numeric::poly::refine_root(theta_name, &coef, c_iso, p)?;
                    let (th, th_err) = crate::numeric::root::acos_newton(&c, p);
                    let sin = Float::with_val(p, 1u32 - Float::with_val(p, c.square_ref())).sqrt();
                    let mut err = Float::with_val(p, &eps / &sin);
                    err += Float::with_val(p, &err >> 16);
                    err += th_err;
                    (Float::with_val(p, th - &th0), err)
                }
            };
            let th = Float::with_val(p, &th0 + &delta);
            let one = Float::with_val(p, 1u32);
            let mut out = vec![if derr.is_zero() {
                Estimate::rounded(self.route.odd(th), one.clone())
            } else {
                Estimate::new(self.route.odd(th), derr.clone(), one.clone())
            }];
            if let Some(name) = value {
                let sf = self.route.scale_force(p);
                let e = self.route.engine(p)?;
                let q = |d: &Float| -> Float {
                    let f = e.dynm.forces(&e.dynm.state(d));
                    match name {
                        "N1_min" => f.n1,
                        "mu_contact_max" => Float::with_val(p, f.f21.abs_ref()) / &f.n12,
                        _ => Float::with_val(p, f.f1.abs_ref()) / &f.n1,
                    }
                };
                let v = q(&delta);
                let mut err = Float::new(p);
                if !derr.is_zero() {
                    for sg in [1i32, -1] {
                        let d2 = Float::with_val(p, &delta + Float::with_val(p, &derr * sg));
                        if d2.is_sign_negative() {
                            continue;
                        }
                        let dv = Float::with_val(p, &q(&d2) - &v).abs();
                        if dv > err {
                            err = dv;
                        }
                    }
                }
                let ulps = Float::with_val(p, v.abs_ref()) >> (p as i32 - 4);
                err += ulps;
                let scale = if name == "N1_min" { sf } else { one };
                out.push(Estimate::new(v, err, scale));
            }
            Ok(out)
        })
    }

    /// Sign-change angles, N1 > 0, friction needed, slip angles for μ.
    pub fn separation_findings(
        &mut self,
        theta_s: &Verified,
        extra: &mut Vec<Verified>,
        notes: &mut Vec<String>,
    ) -> Result<()> {
        let digits = self.digits;
        let th0 = self.route.work.start().theta0.to_float(SCAN_PREC);
        let ds_scan = Float::with_val(SCAN_PREC, self.route.odd(theta_s.value.clone())) - &th0;
        let floor = self.route.work.floor();
        let contact = self.route.work.contact();
        let finite = !self.route.work.starts_at_equilibrium();
        let sign = self.route.sign;

        // --- N1 along the motion: its sign, its minimum, the friction the
        // floor needs (from the polynomials in cos θ: certified, not a scan)
        self.n1_findings(&ds_scan, extra, notes)?;

        // --- where φ̇1 and φ1 change sign
        let phi_moves = floor != Floor::Fixed
            && (self.route.red.alpha[1] != 0
                || self.route.red.beta[1] != 0
                || self.route.red.gamma[1] != 0);
        if phi_moves {
            let gamma0 = self.route.red.gamma[1] == 0;
            // where φ̇1's sign change inside the motion lies (δ at the
            // scan's bits): φ1, 0 at the start and monotone until then, has
            // its first sign change after it
            let mut phidot_zero: Option<Float> = None;
            for (name, label) in [
                ("theta_phi1dot_zero", "phi1_dot"),
                ("theta_phi1_zero", "phi1"),
            ] {
                let needs_time = name == "theta_phi1_zero" && !gamma0;
                if needs_time && !finite {
                    notes.push(format!(
                        "{label} sign change not computed: it depends on the (infinite) time"
                    ));
                    continue;
                }
                let f = |e: &mut Engine, d: &Float| -> Float {
                    if name == "theta_phi1dot_zero" {
                        e.phi1_dot(d)
                    } else {
                        e.phi1(d)
                    }
                };
                let step = Float::with_val(SCAN_PREC, &ds_scan / SCAN_STEPS);
                let found = {
                    let scan = self.route.engine(SCAN_PREC)?;
                    // from the start where the value is not 0 there (φ̇1
                    // with ω0 ≠ 0), from φ̇1's zero for φ1 (its extremum),
                    // else a quarter step on (both 0 at a start from rest):
                    // from a quarter step on, a sign change nearer the start
                    // (φ̇1 from ω0 = 10^-4 on) was not seen, and the motion
                    // said they kept their signs
                    let zero = Float::new(SCAN_PREC);
                    let lo0 = match &phidot_zero {
                        Some(d) if name == "theta_phi1_zero" => d.clone(),
                        _ if name == "theta_phi1dot_zero" && !f(scan, &zero).is_zero() => zero,
                        _ => Float::with_val(SCAN_PREC, &step / 4u32),
                    };
                    // include a sliver past θs so a root at separation is seen
                    let hi0 = Float::with_val(SCAN_PREC, &ds_scan + &step);
                    crate::numeric::root::first_sign_change(&lo0, &hi0, SCAN_STEPS + 1, |d| {
                        f(scan, d)
                    })
                };
                // none up to θs: the formulas continued past θs (while θ̇ > 0,
                // up to θ = π) may still change sign there; a property of
                // the formulas the paper discusses, reported as such
                let (found, after) = match found {
                    Some(b) => (Some(b), false),
                    None => {
                        let scan = self.route.engine(SCAN_PREC)?;
                        let lo0 = Float::with_val(SCAN_PREC, &ds_scan + &step);
                        let pi = Float::with_val(SCAN_PREC, rug::float::Constant::Pi);
                        let hi0 = Float::with_val(SCAN_PREC, &pi - &th0);
                        let hi0 = Float::with_val(
                            SCAN_PREC,
                            &hi0 - (Float::with_val(SCAN_PREC, &hi0 >> 10)),
                        );
                        let b = if hi0 > lo0 {
                            crate::numeric::root::first_sign_change(&lo0, &hi0, SCAN_STEPS, |d| {
                                f(scan, d)
                            })
                        } else {
                            None
                        };
                        (b, true)
                    }
                };
                match found {
                    None => notes.push(format!(
                        "{label} keeps its sign from the start to separation (and on the formulas \
                         continued up to theta = pi)"
                    )),
                    Some((lo, hi)) => {
                        let v = ladder(digits, &[name], |p| {
                            let (d, err) =
                                self.route
                                    .engine(p)?
                                    .refine_root(name, &lo, &hi, |e, d| f(e, d))?;
                            let th =
                                Float::with_val(p, self.route.work.start().theta0.to_float(p) + d);
                            Ok(vec![Estimate::new(
                                self.route.odd(th),
                                err,
                                Float::with_val(p, 1u32),
                            )])
                        })?;
                        let v = v.into_iter().next().expect("one");
                        let bound =
                            Float::with_val(v.value.prec(), &v.err_bound + &theta_s.err_bound);
                        let gap = Float::with_val(v.value.prec(), &v.value - &theta_s.value).abs();
                        if gap <= bound {
                            notes.push(format!(
                                "{label} changes sign at separation (equal to all digits verified)"
                            ));
                        } else if after || (v.value.clone() * sign) > (theta_s.value.clone() * sign)
                        {
                            // past θs: marked in its name and in a note
                            let mut v = v;
                            v.name = format!("{name}_after_separation");
                            notes.push(format!(
                                "{label} keeps its sign from the start to separation; the formulas \
                                 continued past theta_s change its sign at theta = {} \
                                 ({}: a property of the formulas, not of the motion)",
                                v.text, v.name
                            ));
                            extra.push(v);
                            continue;
                        }
                        if name == "theta_phi1dot_zero" {
                            phidot_zero = Some(
                                Float::with_val(SCAN_PREC, self.route.odd(v.value.clone())) - &th0,
                            );
                        }
                        extra.push(v);
                    }
                }
            }
        }

        // --- friction: F21 at separation (μ needed at the contact diverges if ≠ 0)
        if contact == Contact::Roll {
            let v = ladder(digits, &["F21_at_s"], |p| {
                let (ds, err) = self.route.delta_s(p)?;
                let sf = self.route.scale_force(p);
                let e = self.route.engine(p)?;
                let st = e.dynm.state(&ds);
                let f = e.dynm.forces(&st);
                let d2 = Float::with_val(p, &ds + &err);
                let f2 = e.dynm.forces(&e.dynm.state(&d2));
                let prop = Float::with_val(p, &f2.f21 - &f.f21).abs();
                Ok(vec![Estimate::new(self.route.odd(f.f21), prop, sf)])
            })?;
            if v[0].text != "0" {
                notes.push(
                    "F21 != 0 at separation while N12 -> 0: the friction coefficient the contact needs, |F21|/N12, grows without bound as theta -> theta_s, so the upper cylinder slips before it separates for any finite mu"
                        .to_string(),
                );
            }
            extra.extend(v);
        }
        if let Some(mu) = self.mu.clone() {
            let checks: Vec<(&str, bool)> = vec![
                ("theta_slip_floor", floor == Floor::Roll),
                ("theta_slip_contact", contact == Contact::Roll),
            ];
            for (name, applies) in checks {
                if !applies {
                    continue;
                }
                let floor_side = name == "theta_slip_floor";
                let g = move |e: &mut Engine, d: &Float, mu: &Float| -> Float {
                    let st = e.dynm.state(d);
                    let f = e.dynm.forces(&st);
                    let (fr, n) = if floor_side {
                        (f.f1, f.n1)
                    } else {
                        (f.f21, f.n12)
                    };
                    Float::with_val(d.prec(), mu * n) - fr.abs()
                };
                let found = {
                    let mu_s = mu.to_float(SCAN_PREC);
                    let scan = self.route.engine(SCAN_PREC)?;
                    let z = Float::new(SCAN_PREC);
                    crate::numeric::root::first_sign_change(&z, &ds_scan, SCAN_STEPS, |d| {
                        g(scan, d, &mu_s)
                    })
                };
                match found {
                    None => notes.push(format!(
                        "{name}: rolling holds up to separation with mu = {mu}"
                    )),
                    Some((lo, hi)) => {
                        let v = ladder(digits, &[name], |p| {
                            let mu_p = mu.to_float(p);
                            let (d, err) =
                                self.route
                                    .engine(p)?
                                    .refine_root(name, &lo, &hi, |e, d| g(e, d, &mu_p))?;
                            let th =
                                Float::with_val(p, self.route.work.start().theta0.to_float(p) + d);
                            Ok(vec![Estimate::new(
                                self.route.odd(th),
                                err,
                                Float::with_val(p, 1u32),
                            )])
                        })?;
                        extra.extend(v);
                    }
                }
            }
        }
        Ok(())
    }
}
