//! The report's tables, closed forms and CSV files.

use super::data::{
    paper_ref, variant_name, Data, FloorKey, PlaneKey, FORCE_ANGLES, MU_VALUES, PLANE_K2,
    PLANE_TABLE_RATIOS, TABLE_STARTS, VARIANTS,
};
use super::page::{num, Section, Table};
use super::Config;
use crate::error::Result;
use crate::exact::Exact;
use crate::model::{Contact, Floor};
use crate::numeric::decimal::to_sig;
use crate::numeric::verify::Verified;
use crate::oracle::Separation;
use rug::float::Constant;
use rug::Float;

/// Working precision of the closed forms (bits): far beyond any digits shown.
const CF_PREC: u32 = 512;

/// The closed form of θs for identical solid cylinders (k2 = 1/2) from rest
/// at `theta0`, where one is known: (formula, value).
///
/// - both rolling, θ0 → 0+: π/3;
/// - no friction anywhere, θ0 → 0+: arccos(√3 − 1), the corrected eq. (43)
///   m2 cos³θs = (m1 + m2)(3 cos θs − 2) with m1 = m2;
/// - fixed lower cylinder, rolling contact: cos θs = 2 cos θ0 / (3 + k2)
///   (eq. 36 for θ0 = 0: energy (1 + k2) r θ̇²/2 = g (cos θ0 − cos θ) and
///   separation at r θ̇² = g cos θ);
/// - fixed lower cylinder, frictionless contact: cos θs = 2 cos θ0 / 3.
pub fn closed_form(v: (Floor, Contact), theta0: &str) -> Result<Option<(String, Float)>> {
    let p = CF_PREC;
    let th0 = Exact::parse("theta0", theta0, true)?;
    let at_top = th0.is_zero();
    let c0 = th0.to_float(p).cos();
    Ok(match v {
        (Floor::Roll, Contact::Roll) if at_top => {
            Some(("π/3".to_string(), Float::with_val(p, Constant::Pi) / 3u32))
        }
        (Floor::Slip, Contact::Slip) if at_top => {
            let c = Float::with_val(p, 3u32).sqrt() - 1u32;
            Some(("arccos(√3 − 1), eq. (43) corrected".to_string(), c.acos()))
        }
        (Floor::Fixed, Contact::Roll) => {
            Some(fixed_form(&c0, 4, 7, at_top, "arccos(4/7), eq. (36)"))
        }
        (Floor::Fixed, Contact::Slip) => Some(fixed_form(&c0, 2, 3, at_top, "arccos(2/3)")),
        _ => None,
    })
}

/// A fixed lower cylinder's cos θs = (num/den) cos θ0: (formula, θs), the
/// formula `at_top` when θ0 = 0.
fn fixed_form(c0: &Float, num: u32, den: u32, at_top: bool, top: &str) -> (String, Float) {
    let c = Float::with_val(CF_PREC, c0 * num) / den;
    let f = if at_top {
        top.to_string()
    } else {
        format!("arccos({num} cos θ₀ / {den})")
    };
    (f, c.acos())
}

/// arccos(2/(3 + k2)) for an exact k2 (the fixed lower cylinder, eq. 36).
pub fn fixed_lower(k2: &str) -> Result<Float> {
    let k = Exact::parse("k2", k2, false)?.to_float(CF_PREC);
    let c = Float::with_val(CF_PREC, 2u32) / (k + 3u32);
    Ok(c.acos())
}

fn err_cell(e: &crate::error::Error) -> String {
    let s = e.to_string();
    let short: String = s.chars().take(90).collect();
    format!("not verified: {short}")
}

fn extra<'a>(s: &'a Separation, name: &str) -> Option<&'a Verified> {
    s.extra.iter().find(|v| v.name == name)
}

/// Whether a closed-form value agrees with a verified one: the verified text
/// equals the closed form rounded to the same digits.
fn agrees(v: &Verified, cf: &Float) -> (String, bool) {
    let text = to_sig(cf, v.digits.max(1));
    let ok = text == v.text;
    (text, ok)
}

fn degrees(v: &Verified) -> String {
    num(format!("{:.6}", v.value.to_f64().to_degrees()))
}

/// All tables, the notes and the problems met.
pub struct Tables {
    /// Tables in page order.
    pub tables: Vec<Table>,
    /// Findings and problems, as page text.
    pub notes: Section,
    /// Problems worth a line in the run's summary.
    pub problems: Vec<String>,
}

/// A table: the page's description of it (anchor, title, text before it,
/// column headers) and its rows.
fn table(
    id: &str,
    title: &str,
    intro: String,
    header: Vec<String>,
    rows: Vec<Vec<String>>,
) -> Table {
    Table {
        id: id.into(),
        title: title.into(),
        intro,
        header,
        rows,
        csv: format!("{id}.csv"),
    }
}

/// Column headers from texts.
fn cols<S: AsRef<str>>(names: impl IntoIterator<Item = S>) -> Vec<String> {
    names.into_iter().map(|s| s.as_ref().to_string()).collect()
}

/// "yes, all N digits" or "NO".
fn agree_text(ok: bool, digits: u32) -> String {
    if ok {
        format!("yes, all {digits} digits")
    } else {
        "NO".to_string()
    }
}

/// The tables being built and the problems met on the way (in page order).
struct Builder<'a> {
    data: &'a Data,
    cfg: &'a Config,
    problems: Vec<String>,
}

impl Builder<'_> {
    /// The text of a computed value: `ok` of it, its error (recorded as a
    /// problem, `what` first), or "missing".
    fn cell<T>(
        &mut self,
        r: Option<&Result<T>>,
        what: impl FnOnce() -> String,
        ok: impl FnOnce(&T) -> String,
    ) -> String {
        match r {
            Some(Ok(v)) => ok(v),
            Some(Err(e)) => {
                self.problems.push(format!("{}: {e}", what()));
                err_cell(e)
            }
            None => "missing".into(),
        }
    }
}

/// One separation: the cells of tables 1 and 2.
struct SepCells {
    theta: String,
    ts: String,
    f21: String,
    deg: String,
    cf_val: String,
    agree: String,
}

impl SepCells {
    fn same(c: String) -> Self {
        SepCells {
            theta: c.clone(),
            ts: c.clone(),
            f21: c.clone(),
            deg: c.clone(),
            cf_val: c.clone(),
            agree: c,
        }
    }
}

impl Builder<'_> {
    /// The cells of a verified separation, its closed form checked.
    fn sep_cells(
        &mut self,
        v: (Floor, Contact),
        th0: &str,
        s: &Separation,
        cf: &Option<(String, Float)>,
    ) -> SepCells {
        let (cf_text, agree) = match cf {
            Some((_, val)) => {
                let (t, ok) = agrees(&s.theta_s, val);
                if !ok {
                    self.problems.push(format!(
                        "{} from theta0 = {th0}: theta_s = {} but the closed form gives {t}",
                        variant_name(v),
                        s.theta_s.text
                    ));
                }
                (num(&t), agree_text(ok, s.theta_s.digits))
            }
            None => ("—".to_string(), "—".to_string()),
        };
        let f21 = extra(s, "F21_at_s");
        SepCells {
            theta: num(&s.theta_s.text),
            ts: match &s.t_s {
                Some(t) => num(&t.text),
                None => "∞ (start at rest at the top)".to_string(),
            },
            f21: f21.map_or_else(|| "0 (frictionless)".to_string(), |f| num(&f.text)),
            deg: degrees(&s.theta_s),
            cf_val: cf_text,
            agree,
        }
    }

    /// Tables 1 (from the top) and 2 (from small starts).
    fn separation(&mut self) -> Result<(Table, Table)> {
        let d = self.cfg.digits;
        let (mut top, mut start) = (Vec::new(), Vec::new());
        for (vi, v) in VARIANTS.iter().enumerate() {
            for (si, th0) in TABLE_STARTS.iter().enumerate() {
                let cf = closed_form(*v, th0)?;
                let c = match self.data.sep.get(vi).and_then(|s| s.get(si)) {
                    Some(Ok(s)) => self.sep_cells(*v, th0, s, &cf),
                    Some(Err(e)) => {
                        self.problems
                            .push(format!("{} from theta0 = {th0}: {e}", variant_name(*v)));
                        SepCells::same(err_cell(e))
                    }
                    None => SepCells::same("missing".to_string()),
                };
                let formula = cf.map_or_else(|| "—".into(), |c| c.0);
                let name = variant_name(*v);
                if si == 0 {
                    let paper = paper_ref(*v).to_string();
                    top.push(vec![
                        name, paper, c.theta, c.deg, formula, c.cf_val, c.agree, c.f21,
                    ]);
                } else {
                    start.push(vec![
                        name,
                        num(th0),
                        c.theta,
                        c.ts,
                        formula,
                        c.cf_val,
                        c.agree,
                    ]);
                }
            }
        }
        let t1 = table(
            "separation-top",
            "Separation from rest at the top (θ₀ → 0+)",
            format!(
                "Identical solid cylinders (m₁ = m₂, r₁ = r₂, k₁ = k₂ = 1/2), every contact model, started from rest \
                 with the upper cylinder on top (the paper's case, the limit θ₀ → 0+; the time is then infinite). \
                 θₛ in radians to {d} verified significant digits; the closed form, where one is known, is evaluated \
                 independently at {CF_PREC} bits and rounded to the same digits. F₂₁ at separation is in units of m₁g: \
                 where it is not zero, the friction coefficient that rolling needs diverges as θ → θₛ."
            ),
            cols(["contact model", "paper", "θₛ [rad]", "θₛ [deg], rounded", "closed form", "closed form value", "agrees", "F₂₁ at θₛ [m₁g]"]),
            top,
        );
        let t2 = table(
            "separation-start",
            "Separation from rest at θ₀ = 1/100 and θ₀ = 1/20",
            format!(
                "The same cylinders started from rest a little off the top: θₛ [rad] and the time tₛ to separation \
                 [τ = √(r₁/g)], {d} verified digits. For the fixed lower cylinder the closed form is \
                 cos θₛ = 2 cos θ₀ / (3 + k₂) (rolling contact) or 2 cos θ₀ / 3 (frictionless contact)."
            ),
            cols(["contact model", "θ₀ [rad]", "θₛ [rad]", "tₛ [τ]", "closed form", "closed form value", "agrees"]),
            start,
        );
        Ok((t1, t2))
    }

    /// Table 3: the forces of the main case at chosen angles.
    fn forces(&mut self) -> Table {
        let names = [
            "F₁ [m₁g]",
            "N₁ [m₁g]",
            "F₂₁ [m₁g]",
            "N₁₂ [m₁g]",
            "dθ/dt [rad/τ]",
            "d²θ/dt² [rad/τ²]",
            "μ needed at the floor, |F₁|/N₁",
            "μ needed between the cylinders, |F₂₁|/N₁₂",
        ];
        let data = self.data;
        let mut rows = Vec::new();
        for (qi, name) in names.iter().enumerate() {
            let mut row = vec![name.to_string()];
            for (ai, a) in FORCE_ANGLES.iter().enumerate() {
                let r = data.forces.get(ai);
                let value = |f: &Vec<Verified>| f.get(qi).map(|v| num(&v.text)).unwrap_or_default();
                row.push(match r {
                    // an angle's error is recorded once, on the first row
                    Some(Err(e)) if qi > 0 => err_cell(e),
                    _ => self.cell(r, || format!("forces at theta = {a}"), value),
                });
            }
            rows.push(row);
        }
        let angle = |a: &&str| {
            let t = a.replace("pi", "π");
            if t.contains('π') {
                format!("θ = {t}")
            } else {
                format!("θ = {t} rad")
            }
        };
        table(
            "forces",
            "Forces in the main case at chosen angles",
            format!(
                "Both contacts rolling, identical solid cylinders, from rest at the top (θ₀ → 0+); {} verified digits; \
                 m₁ = m₂ = r₁ = r₂ = g = 1.",
                self.cfg.digits
            ),
            cols(["quantity".to_string()].into_iter().chain(FORCE_ANGLES.iter().map(angle))),
            rows,
        )
    }

    /// Table 4: where rolling first fails for a friction coefficient μ.
    fn friction(&mut self) -> Table {
        let mut rows = Vec::new();
        for (i, mu) in MU_VALUES.iter().enumerate() {
            let row = match self.data.mu.get(i) {
                Some(Ok(s)) => slip_row(mu, s),
                r => {
                    let c = self.cell(
                        r,
                        || format!("slip angles for mu = {mu}"),
                        |_| String::new(),
                    );
                    vec![num(mu), c, String::new(), String::new(), String::new()]
                }
            };
            rows.push(row);
        }
        table(
            "friction",
            "Where rolling first fails, for a friction coefficient μ",
            format!(
                "Main case (both contacts rolling, identical solid cylinders, from rest at the top): the first angle \
                 at which rolling without slipping would need more friction than μ, at the floor (|F₁| > μN₁) and \
                 between the cylinders (|F₂₁| > μN₁₂); {} verified digits. Past that angle the rolling model no longer \
                 applies. Between the cylinders it always fails before θₛ, since N₁₂ → 0 while F₂₁ does not.",
                self.cfg.digits
            ),
            cols(["μ", "floor slips at θ [rad]", "cylinders slip at θ [rad]", "slips first", "θₛ [rad]"]),
            rows,
        )
    }

    /// The cells of a fixed lower cylinder's θs next to its closed form.
    fn fixed_cells(&mut self, k2: &str) -> Result<[String; 3]> {
        let d = self.cfg.digits;
        let key = PlaneKey {
            floor: FloorKey::Fixed,
            ratio: "1".to_string(),
            k2: k2.to_string(),
            digits: d,
        };
        let cf = fixed_lower(k2)?;
        Ok(match self.data.plane.get(&key) {
            Some(Ok(v)) => {
                let (t, ok) = agrees(v, &cf);
                if !ok {
                    self.problems.push(format!(
                        "fixed lower cylinder, k2 = {k2}: theta_s = {} but arccos(2/(3+k2)) = {t}",
                        v.text
                    ));
                }
                [num(&v.text), num(&t), agree_text(ok, v.digits)]
            }
            r => {
                let c = self.cell(
                    r,
                    || format!("fixed lower cylinder, k2 = {k2}"),
                    |_| String::new(),
                );
                [c, num(to_sig(&cf, d)), "—".into()]
            }
        })
    }

    /// Table 5: θs at chosen points of the parameter plane.
    fn plane(&mut self) -> Table {
        let td = self.cfg.plane_table_digits;
        let mut rows = Vec::new();
        for k2 in PLANE_K2 {
            let mut row = vec![num(k2)];
            for r in PLANE_TABLE_RATIOS {
                let key = PlaneKey {
                    floor: FloorKey::Roll,
                    ratio: r.to_string(),
                    k2: k2.to_string(),
                    digits: td,
                };
                let what = || format!("plane m₂/m₁ = {r}, k2 = {k2}");
                row.push(self.cell(self.data.plane.get(&key), what, |v| num(&v.text)));
            }
            rows.push(row);
        }
        let ratios = PLANE_TABLE_RATIOS.iter().map(|r| format!("m₂/m₁ = {r}"));
        table(
            "plane-points",
            "θₛ at chosen points of the parameter plane",
            format!(
                "θₛ [rad] with both contacts rolling, from rest at the top, m₁ = r₁ = r₂ = g = 1, k₁ = 1/2, for \
                 several mass ratios m₂/m₁ and k₂ ({td} verified digits). As m₂/m₁ → 0 the lower cylinder stops \
                 moving and θₛ tends to the held-lower value of the next table."
            ),
            cols(["k₂".to_string()].into_iter().chain(ratios)),
            rows,
        )
    }

    /// Table 6: a held lower cylinder's θs against its closed form.
    fn plane_fixed(&mut self) -> Result<Table> {
        let mut rows = Vec::new();
        for k2 in PLANE_K2 {
            let mut row = vec![num(k2)];
            row.extend(self.fixed_cells(k2)?);
            rows.push(row);
        }
        Ok(table(
            "plane-fixed",
            "θₛ of a held lower cylinder against its closed form",
            format!(
                "The lower cylinder held fixed, the contact rolling, from rest at the top: the oracle's θₛ [rad] \
                 ({} verified digits) next to the closed form arccos(2/(3 + k₂)) of eq. (36), evaluated \
                 independently and rounded to the same digits.",
                self.cfg.digits
            ),
            cols(["k₂", "θₛ, oracle", "arccos(2/(3 + k₂))", "agrees"]),
            rows,
        ))
    }

    /// Points of the parameter plane that could not be verified, as a problem.
    fn plane_failures(&mut self) {
        let failed = self.data.plane.values().filter(|v| v.is_err()).count();
        if failed > 0 {
            self.problems.push(format!(
                "{failed} parameter-plane points could not be verified and are left out of the figures"
            ));
        }
    }

    /// Points of a variant's curves that could not be verified or computed,
    /// as notes (and problems).
    fn curve_notes(&mut self, vi: usize, v: (Floor, Contact), items: &mut Vec<String>) {
        let data = self.data;
        let skipped = [
            (
                "time",
                data.time
                    .get(vi)
                    .and_then(|r| r.as_ref().ok())
                    .map(|c| &c.skipped),
            ),
            (
                "theta",
                data.theta
                    .get(vi)
                    .and_then(|r| r.as_ref().ok())
                    .map(|c| &c.skipped),
            ),
        ];
        for (what, sk) in skipped {
            if let Some(sk) = sk.filter(|sk| !sk.is_empty()) {
                items.push(format!(
                    "{}: {} plotted points against {what} could not be verified to {} digits and are left out (first: {} = {}: {})",
                    variant_name(v),
                    sk.len(),
                    self.cfg.plot_digits,
                    what,
                    sk[0].0,
                    sk[0].1
                ));
            }
        }
        let failed = [
            (
                "the trajectory",
                data.time.get(vi).and_then(|r| r.as_ref().err()),
            ),
            (
                "the forces against θ",
                data.theta.get(vi).and_then(|r| r.as_ref().err()),
            ),
        ];
        for (what, e) in failed {
            if let Some(e) = e {
                items.push(format!(
                    "{}: {what} could not be computed: {e}",
                    variant_name(v)
                ));
            }
        }
    }

    /// The section "What the oracle reported": each model's findings, then
    /// every problem.
    fn notes(&mut self) -> Section {
        let mut items = Vec::new();
        for (vi, v) in VARIANTS.iter().enumerate() {
            if let Some(Ok(s)) = self.data.sep.get(vi).and_then(|s| s.first()) {
                items.push(format!("{}: {}", variant_name(*v), reader_notes(*v, s)));
            }
        }
        for (vi, v) in VARIANTS.iter().enumerate() {
            let before = items.len();
            self.curve_notes(vi, *v, &mut items);
            self.problems.extend(items[before..].iter().cloned());
        }
        for p in &self.problems {
            if !items.contains(p) {
                items.push(p.clone());
            }
        }
        Section {
            title: "What the oracle reported".into(),
            paragraphs: vec![format!(
                "What the oracle found for each contact model, started from rest at the top (the limit θ₀ → 0+, where the \
                 time to separation is infinite), with its verified values rounded here to 6 decimals (to {} digits in \
                 `separation-top.csv` and from `cylroll separation`). Forces are in units of m₁g. Any point that could not be \
                 verified is listed here too.",
                self.cfg.digits
            )],
            items,
            links: Vec::new(),
        }
    }
}

/// A row of table 4 for a verified μ.
fn slip_row(mu: &str, s: &Separation) -> Vec<String> {
    let fl = extra(s, "theta_slip_floor");
    let ct = extra(s, "theta_slip_contact");
    let cell = |v: Option<&Verified>| match v {
        Some(v) => num(&v.text),
        None => "rolls until separation".to_string(),
    };
    let first = match (fl, ct) {
        (Some(a), Some(b)) if a.value < b.value => "the floor",
        (Some(_), Some(_)) | (None, Some(_)) => "the contact between the cylinders",
        (Some(_), None) => "the floor",
        (None, None) => "neither",
    };
    vec![
        num(mu),
        cell(fl),
        cell(ct),
        first.to_string(),
        num(&s.theta_s.text),
    ]
}

/// Builds every table from the data.
pub fn tables(data: &Data, cfg: &Config) -> Result<Tables> {
    let mut b = Builder {
        data,
        cfg,
        problems: Vec::new(),
    };
    let (t1, t2) = b.separation()?;
    let t3 = b.forces();
    let t4 = b.friction();
    let t5 = b.plane();
    let t6 = b.plane_fixed()?;
    b.plane_failures();
    let notes = b.notes();
    Ok(Tables {
        tables: vec![t1, t2, t3, t4, t5, t6],
        notes,
        problems: b.problems,
    })
}

/// A verified value rounded for prose.
fn r6(v: &Verified) -> String {
    let x = v.value.to_f64();
    super::model::minus(&format!("{x:.6}"))
}

/// Plain words for the oracle's technical names in a note it wrote.
fn plain(note: &str) -> String {
    let mut t = note.to_string();
    for (a, b) in [
        ("theta_s", "θₛ"),
        ("theta0", "θ₀"),
        ("phi1_dot", "dφ₁/dt"),
        ("phi1", "φ₁"),
        ("phi2", "φ₂"),
        ("theta", "θ"),
        ("N12", "N₁₂"),
        ("N1", "N₁"),
        ("F21", "F₂₁"),
        ("F1", "F₁"),
        ("t_s", "tₛ"),
        (" != ", " ≠ "),
        (" -> ", " → "),
        ("0+", "0⁺"),
        ("K^2", "K²"),
    ] {
        t = t.replace(a, b);
    }
    t
}

/// The oracle's findings for one contact model, written for a reader: the
/// lower cylinder's normal force, the friction the floor needs, the turning
/// of cylinder 1, the friction at separation, then any other note.
pub fn reader_notes(v: (Floor, Contact), s: &Separation) -> String {
    let held = v.0 == Floor::Fixed;
    let mut out = floor_notes(held, s);
    if !held && v != (Floor::Slip, Contact::Slip) {
        out.extend(turning_notes(s));
    }
    if let Some(f) = extra(s, "F21_at_s") {
        out.push(format!(
            "at separation F₂₁ = {} while N₁₂ → 0, so the friction a rolling contact needs, |F₂₁|/N₁₂, grows without bound: with \
             any finite μ the upper cylinder slips before it separates",
            r6(f)
        ));
    }
    // notes not said above, in plain words
    let said = ["t_s is infinite", "N1 > 0", "N1 ", "phi1", "F21 != 0"];
    for n in &s.notes {
        if !said.iter().any(|p| n.starts_with(p)) {
            out.push(plain(n));
        }
    }
    // verified values not said above
    let known = [
        "F21_at_s",
        "N1_min",
        "theta_N1_min",
        "theta_N1_zero",
        "mu_floor_max",
        "theta_mu_floor_max",
        "theta_phi1dot_zero",
        "theta_phi1_zero",
        "theta_phi1dot_zero_after_separation",
        "theta_phi1_zero_after_separation",
    ];
    for x in &s.extra {
        if !known.contains(&x.name.as_str()) {
            out.push(format!("{} = {}", plain(&x.name), r6(x)));
        }
    }
    let mut text = out.join("; ");
    if let Some(first) = text.get(..1) {
        text = first.to_uppercase() + &text[1..];
    }
    text.push('.');
    text
}

/// What the floor (or the holder) does: N₁ and the friction it needs.
fn floor_notes(held: bool, s: &Separation) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    let n1 = extra(s, "N1_min").zip(extra(s, "theta_N1_min"));
    let lift = extra(s, "theta_N1_zero");
    match (held, lift, n1) {
        (_, Some(a), _) => out.push(format!(
            "N₁ reaches 0 at θ = {} before separation: cylinder 1 would leave {} first",
            r6(a),
            if held { "its holder" } else { "the floor" }
        )),
        (true, None, Some((m, a))) => out.push(format!(
            "cylinder 1 is held: the holder's vertical force N₁ stays positive up to separation (checked at every angle), \
             smallest {} at θ = {}",
            r6(m),
            r6(a)
        )),
        (false, None, Some((m, a))) => out.push(format!(
            "cylinder 1 stays on the floor: N₁ > 0 at every angle up to separation (N₁ has no root there), smallest {} at θ = {}",
            r6(m),
            r6(a)
        )),
        _ => {}
    }
    if let (Some(m), Some(a)) = (extra(s, "mu_floor_max"), extra(s, "theta_mu_floor_max")) {
        out.push(if held {
            format!(
                "the holder's horizontal force is at most |F₁|/N₁ = {} of its vertical force (at θ = {})",
                r6(m),
                r6(a)
            )
        } else {
            format!(
                "rolling on the floor needs a friction coefficient of at most |F₁|/N₁ = {} (at θ = {})",
                r6(m),
                r6(a)
            )
        });
    }
    out
}

/// Where cylinder 1's rotation rate and angle change sign.
fn turning_notes(s: &Separation) -> Vec<String> {
    let mut out = Vec::new();
    for (key, name) in [("phi1dot", "dφ₁/dt"), ("phi1", "φ₁")] {
        let before = extra(s, &format!("theta_{key}_zero"));
        let after = extra(s, &format!("theta_{key}_zero_after_separation"));
        let ths = s.theta_s.value.to_f64();
        out.push(match (before, after) {
            (Some(a), _) if (a.value.to_f64() - ths).abs() < 1e-12 * ths.max(1.0) => {
                format!("{name} reaches 0 exactly at separation")
            }
            (Some(a), _) => format!("{name} changes sign at θ = {}, before separation", r6(a)),
            (None, Some(a)) => format!(
                "{name} keeps its sign up to separation (continued past θₛ, the formulas would change it at θ = {}, which the \
                 motion never reaches)",
                r6(a)
            ),
            (None, None) => format!("{name} keeps its sign up to separation"),
        });
    }
    out
}
