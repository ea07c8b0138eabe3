//! The report's figures, built from [`Data`] as [`Figure`] values.
//!
//! Captions are written from the data they describe: every claim in a
//! caption (a sign that does not change, a maximum, where a contour runs) is
//! computed here from the plotted or verified values, never written in
//! advance.

use super::data::{
    k2_grid, log_grid, text_f64, variant_name, variant_stem, Data, FloorKey, PlaneKey, ThetaCurve,
    TimeCurve, MU_VALUES, PLANE_K2, PLANE_TABLE_RATIOS, THETA0_TIME, VARIANTS,
};
use super::plot::{
    chain, contour, minus, nice_ticks, viridis, ColorBar, Dash, Figure, Label, LegendEntry, Marker,
    Panel, Raster, RefLine, Scale, Series, Shape, PALETTE, SHAPES,
};
use super::Config;
use crate::model::{Contact, Floor};
use crate::oracle::Separation;

/// Trajectory columns.
const T: usize = 0;
const TH: usize = 1;
const THD: usize = 2;
const PHI1: usize = 4;
const PHI2: usize = 5;
/// Force columns of a trajectory row (F1, N1, F21, N12).
const TF: [usize; 4] = [9, 10, 11, 12];
/// Force columns of a θ row (θ first, then F1, N1, F21, N12, θ̇, θ̈, μ floor, μ contact).
const AF: [usize; 4] = [1, 2, 3, 4];
const MU_FLOOR: usize = 7;
const MU_CONTACT: usize = 8;

/// The forces' names, with subscripts.
pub const FORCE_NAMES: [&str; 4] = ["F₁", "N₁", "F₂₁", "N₁₂"];
const FORCE_LONG: [&str; 4] = [
    "F₁: horizontal force of the floor on cylinder 1 (+x to the right)",
    "N₁: normal force of the floor on cylinder 1 (+ upwards)",
    "F₂₁: tangential force of cylinder 1 on cylinder 2, along (cos θ, −sin θ)",
    "N₁₂: normal force between the cylinders (+ while they press)",
];
const FORCE_DASH: [Dash; 4] = [Dash::Solid, Dash::Dashed, Dash::DashDot, Dash::Dotted];

/// A variant's curve of one force: (variant, points, tₛ, θₛ).
type Curve = (usize, Vec<(f64, f64)>, f64, f64);

/// Time unit text.
pub const TAU: &str = "τ = √(r₁/g)";
const T_LABEL: &str = "t  [τ]";
const TS_LABEL: &str = "t − tₛ  [τ]  (time to separation)";
const THETA_LABEL: &str = "θ  [rad]";
const FORCE_LABEL: &str = "force  [m₁g]";
const SEP_COLOR: (u8, u8, u8) = (90, 90, 90);

fn variant_color(v: usize) -> (u8, u8, u8) {
    PALETTE[v % PALETTE.len()]
}

/// Line style by floor: rolling solid, frictionless dashed, fixed dash-dot.
fn variant_dash(v: usize) -> Dash {
    match VARIANTS[v].0 {
        Floor::Roll => Dash::Solid,
        Floor::Slip => Dash::Dashed,
        Floor::Fixed => Dash::DashDot,
    }
}

/// Short name of a variant for direct labels: floor/contact.
pub fn variant_short(v: usize) -> String {
    format!("{}/{}", VARIANTS[v].0, VARIANTS[v].1)
}

fn variant_legend(v: usize) -> String {
    format!("{} ({})", variant_name(VARIANTS[v]), variant_short(v))
}

/// Whether force `i` (F1, N1, F21, N12) vanishes identically in variant `v`.
pub fn force_is_zero(v: usize, i: usize) -> bool {
    let (floor, contact) = VARIANTS[v];
    (i == 0 && floor == Floor::Slip) || (i == 2 && contact == Contact::Slip)
}

fn column(rows: &[Vec<f64>], x: usize, y: usize) -> Vec<(f64, f64)> {
    rows.iter()
        .filter_map(|r| Some((*r.get(x)?, *r.get(y)?)))
        .collect()
}

/// A number for a label, with `dec` decimals and a true minus sign.
pub fn fmt(v: f64, dec: usize) -> String {
    minus(&format!("{v:.dec$}"))
}

/// A verified extra value of a separation, as f64.
pub fn extra_f(s: &Separation, name: &str) -> Option<f64> {
    s.extra
        .iter()
        .find(|v| v.name == name)
        .map(|v| v.value.to_f64())
}

/// Periodic markers: about 7 per curve, staggered by curve index so that
/// markers of different curves do not sit on one another.
fn stagger(s: Series, n_points: usize, index: usize, of: usize) -> Series {
    let every = (n_points / 7).max(2);
    let phase = (every * (index + 1)) / (of + 1);
    s.every(every, phase)
}

/// The separation line of a panel: a vertical dotted line at `x` labelled.
fn sep_line(x: f64, label: String) -> RefLine {
    RefLine {
        at: x,
        vertical: true,
        color: SEP_COLOR,
        dash: Dash::Dotted,
        label,
    }
}

fn sep_legend() -> LegendEntry {
    LegendEntry {
        label: "separation: N₁₂ = 0; each curve ends there with its hollow marker".into(),
        color: SEP_COLOR,
        dash: Some(Dash::Dotted),
        shape: None,
        filled: false,
    }
}

fn end_legend() -> LegendEntry {
    LegendEntry {
        label: "separation (N₁₂ = 0): each curve ends there with its large hollow marker".into(),
        color: SEP_COLOR,
        dash: None,
        shape: Some(Shape::Circle),
        filled: false,
    }
}

/// The four forces of one trajectory or θ curve as series.
fn force_series(
    rows: &[Vec<f64>],
    x: usize,
    cols: [usize; 4],
    v: usize,
    at_end: &str,
) -> Vec<Series> {
    let live: Vec<usize> = (0..4).filter(|&i| !force_is_zero(v, i)).collect();
    live.iter()
        .enumerate()
        .map(|(k, &i)| {
            let pts = column(rows, x, cols[i]);
            let end = pts
                .last()
                .map(|p| format!("{} at {at_end}: {}", FORCE_NAMES[i], fmt(p.1, 4)))
                .unwrap_or_default();
            let n = pts.len();
            stagger(
                Series::new(FORCE_NAMES[i], PALETTE[i], pts)
                    .dashed(FORCE_DASH[i])
                    .shape(SHAPES[i])
                    .end_marker(end),
                n,
                k,
                live.len(),
            )
        })
        .collect()
}

/// The curves that could be computed, with their variant.
fn computed<T>(curves: &[crate::error::Result<T>]) -> Vec<(usize, &T)> {
    curves
        .iter()
        .enumerate()
        .filter_map(|(v, r)| r.as_ref().ok().map(|c| (v, c)))
        .collect()
}

fn start_text() -> String {
    format!("from rest at θ₀ = {THETA0_TIME}")
}

fn t_s(c: &TimeCurve) -> f64 {
    c.sep.t_s.as_ref().map_or(f64::NAN, |t| t.value.to_f64())
}

/// Whether every y of `pts` is zero (to plotting accuracy).
fn all_zero(pts: &[(f64, f64)]) -> bool {
    pts.iter().all(|p| p.1.abs() < 1e-12)
}

/// "changes sign at …" / "keeps its sign" for a sampled curve: the text and
/// whether it changes.
fn sign_text(pts: &[(f64, f64)], xname: &str) -> (String, bool) {
    let mut last: Option<(f64, f64)> = None;
    for &(x, y) in pts {
        if y.abs() < 1e-12 {
            continue;
        }
        if let Some((lx, ly)) = last {
            if (ly < 0.0) != (y < 0.0) {
                let xc = lx + (x - lx) * ly / (ly - y);
                return (format!("changes sign near {xname} ≈ {}", fmt(xc, 3)), true);
            }
        }
        last = Some((x, y));
    }
    let sign = match last {
        Some((_, y)) if y < 0.0 => "< 0",
        Some(_) => "> 0",
        None => "= 0",
    };
    (format!("keeps its sign ({sign}) throughout"), false)
}

/// One time panel: a quantity of every curve given against t (or t − tₛ).
fn time_panel(
    title: &str,
    ylabel: &str,
    curves: &[(usize, &TimeCurve)],
    col: usize,
    shift: bool,
) -> Panel {
    let mut p = Panel::new(title, if shift { TS_LABEL } else { T_LABEL }, ylabel);
    let many = curves.len() > 1;
    let mut zero = Vec::new();
    let n = curves.len();
    for (k, &(v, c)) in curves.iter().enumerate() {
        let ts = t_s(c);
        let mut pts = column(&c.rows, T, col);
        if shift {
            for q in &mut pts {
                q.0 -= ts;
            }
        }
        if many && all_zero(&pts) {
            zero.push(variant_short(v));
            continue;
        }
        let end = format!(
            "{}: separation at t = {}, θₛ = {}; {ylabel} = {}",
            variant_name(VARIANTS[v]),
            fmt(ts, 4),
            fmt(c.sep.theta_s.value.to_f64(), 4),
            pts.last().map_or(String::new(), |q| fmt(q.1, 4))
        );
        let np = pts.len();
        let mut s = Series::new(
            if many {
                variant_legend(v)
            } else {
                String::new()
            },
            if many { variant_color(v) } else { PALETTE[0] },
            pts,
        )
        .dashed(if many { variant_dash(v) } else { Dash::Solid })
        .shape(if many { SHAPES[v] } else { Shape::Circle })
        .end_marker(end);
        if many {
            s = stagger(s.direct(variant_short(v)), np, k, n);
        }
        p.series.push(s);
    }
    if !zero.is_empty() {
        let name = ylabel.split_whitespace().next().unwrap_or(ylabel);
        p.notes.push(format!("{name} ≡ 0 for {}", zero.join(", ")));
    }
    if !many {
        if let Some(&(_, c)) = curves.first() {
            let x = if shift { 0.0 } else { t_s(c) };
            p.lines
                .push(sep_line(x, format!("tₛ = {}", fmt(t_s(c), 4))));
        }
        p.legend.push(sep_legend());
    } else if shift {
        p.lines.push(sep_line(0.0, "separation".into()));
        p.legend.push(sep_legend());
    } else {
        p.legend.push(end_legend());
    }
    p
}

const CYL: &str = "Identical solid cylinders, m₁ = m₂ = r₁ = r₂ = g = 1, k₁ = k₂ = 1/2";

fn forces_units() -> String {
    format!("{CYL}; time unit {TAU}, forces in units of m₁g.")
}

fn kin_units() -> String {
    format!("{CYL}; time unit {TAU}.")
}

/// What the figures are drawn from: the curves that could be computed.
struct Src<'a> {
    data: &'a Data,
    times: Vec<(usize, &'a TimeCurve)>,
    thetas: Vec<(usize, &'a ThetaCurve)>,
}

impl<'a> Src<'a> {
    fn time(&self, v: usize) -> Option<&'a TimeCurve> {
        self.times.iter().find(|(w, _)| *w == v).map(|x| x.1)
    }
    fn theta(&self, v: usize) -> Option<&'a ThetaCurve> {
        self.thetas.iter().find(|(w, _)| *w == v).map(|x| x.1)
    }
    /// The main case's separation from rest at the top (table digits).
    fn main_sep(&self) -> Option<&'a Separation> {
        self.data.sep.first()?.first()?.as_ref().ok()
    }
}

/// All figures, in page order: each is one builder below.
pub fn figures(data: &Data, cfg: &Config) -> Vec<Figure> {
    let src = Src {
        data,
        times: computed(&data.time),
        thetas: computed(&data.theta),
    };
    let mut figs = vec![super::diagram::figure()];
    figs.extend(main_kinematics(&src));
    figs.extend(main_forces_t(&src));
    figs.extend(main_forces_theta(&src));
    figs.extend(
        src.theta(0)
            .map(|c| friction_needed(c, data, src.main_sep())),
    );
    for shift in [false, true] {
        figs.extend(variants_kinematics(&src, shift));
    }
    for axis in [ForceAxis::Time, ForceAxis::ToSeparation, ForceAxis::Theta] {
        figs.push(variants_forces(&src, axis));
    }
    figs.extend((0..VARIANTS.len()).filter_map(|v| variant_forces(&src, v)));
    figs.extend(plane_figures(data, cfg));
    figs
}

/// The vertical line at a curve's separation time, labelled with it.
fn ts_line(c: &TimeCurve, at: f64) -> RefLine {
    sep_line(at, format!("tₛ = {}", fmt(t_s(c), 4)))
}

/// The vertical line at θs, labelled with it.
fn ths_line(ths: f64) -> RefLine {
    sep_line(ths, format!("θₛ = {}", fmt(ths, 4)))
}

/// "dφ₁/dt … separation" for the caption of the main kinematics.
fn phi1dot_text(c: &TimeCurve) -> String {
    let ths = c.sep.theta_s.value.to_f64();
    match extra_f(&c.sep, "theta_phi1dot_zero") {
        Some(a) if (a - ths).abs() < 1e-9 => format!(
            "dφ₁/dt reaches 0 exactly at separation (θ = {}, where cos θ = k₂: the paper's remark after eq. 18)",
            fmt(a, 6)
        ),
        Some(a) => format!(
            "dφ₁/dt changes sign at θ = {} (where cos θ = k₂, the paper's remark after eq. 18), {} separation at θₛ = {}",
            fmt(a, 6),
            if ths - a < 0.01 { "just before" } else { "before" },
            fmt(ths, 6)
        ),
        None => "dφ₁/dt keeps its sign up to separation".into(),
    }
}

fn main_kinematics(src: &Src) -> Option<Figure> {
    let c = src.time(0)?;
    let main_t = [(0, c)];
    let panel =
        |title: &str, ylabel: &str, col: usize| time_panel(title, ylabel, &main_t, col, false);
    let panels = vec![
        panel("θ: line of centres from the vertical", THETA_LABEL, TH),
        panel("dθ/dt", "dθ/dt  [rad/τ]", THD),
        panel("φ₁: clockwise rotation of cylinder 1", "φ₁  [rad]", PHI1),
        panel("φ₂: the paper's angle of cylinder 2", "φ₂  [rad]", PHI2),
    ];
    let (phi1_sign, _) = sign_text(&column(&c.rows, T, PHI1)[1..], "t");
    let ts = t_s(c);
    let after = extra_f(&c.sep, "theta_phi1_zero_after_separation")
        .map(|a| format!(" (the formulas continued past separation would change its sign only at θ = {}, a property of the formulas, not of the motion)", fmt(a, 4)))
        .unwrap_or_default();
    let t_half = c
        .rows
        .iter()
        .find(|r| r[TH] > 0.1)
        .map_or(f64::NAN, |r| r[T]);
    let title = format!("Main case (both contacts rolling), {}", start_text());
    Some(Figure::new("main_kinematics.svg", title, (1200, 820), (2, 2), panels, 210).caption(format!(
        "θ, dθ/dt, φ₁ and φ₂ against time for the paper's main case (§2), {}; separation (N₁₂ = 0) at tₛ = {} \
         (dotted line; hover a marker for the values). The start is slow: θ stays below 0.1 rad until t ≈ {} of {}; \
         the plots against t − tₛ under \"All contact models\" show the last part larger. φ₁ {phi1_sign}{after}; {}. {}",
        start_text(),
        fmt(ts, 4),
        fmt(t_half, 2),
        fmt(ts, 2),
        phi1dot_text(c),
        kin_units(),
    )))
}

fn main_forces_t(src: &Src) -> Option<Figure> {
    let c = src.time(0)?;
    let mut p = Panel::new("", T_LABEL, FORCE_LABEL);
    p.series = force_series(&c.rows, T, TF, 0, "separation");
    p.lines.push(ts_line(c, t_s(c)));
    p.legend.push(sep_legend());
    let (f21_sign, _) = sign_text(&column(&c.rows, T, TF[2])[1..], "t");
    let title = format!("Main case: contact forces against time, {}", start_text());
    Some(Figure::single("main_forces_t.svg", title, (1000, 520), p, 230).caption(format!(
        "The four contact forces against time, main case, {}. {}; {}; {}; {} (see the sign-convention diagram). \
         F₂₁ {f21_sign}: the friction on cylinder 2 points along (−cos θ, sin θ), back up the slope. \
         N₁₂ reaches 0 at separation, tₛ = {}. {}",
        start_text(),
        FORCE_LONG[0],
        FORCE_LONG[1],
        FORCE_LONG[2],
        FORCE_LONG[3],
        fmt(t_s(c), 4),
        forces_units()
    )))
}

/// The slip onsets of the table "Where rolling first fails" on the curves
/// of F₂₁ and F₁ against θ: the markers.
fn onset_markers(c: &ThetaCurve, data: &Data) -> Vec<Marker> {
    let f21 = column(&c.rows, 0, AF[2]);
    let f1 = column(&c.rows, 0, AF[0]);
    let mut out = Vec::new();
    for (mu, r) in MU_VALUES.iter().zip(&data.mu) {
        let Ok(s) = r else { continue };
        for (name, curve, on) in [
            ("theta_slip_contact", &f21, "between the cylinders"),
            ("theta_slip_floor", &f1, "at the floor"),
        ] {
            let Some((a, y)) = extra_f(s, name).and_then(|a| Some((a, interp(curve, a)?))) else {
                continue;
            };
            let title = format!(
                "μ = {mu}: rolling {on} first needs more friction than μ at θ = {}",
                fmt(a, 4)
            );
            out.push(Marker::shaped(
                Shape::TriangleDown,
                (a, y),
                (0, 0, 0),
                title,
                Some(format!("μ={mu}")),
            ));
        }
    }
    out
}

fn main_forces_theta(src: &Src) -> Option<Figure> {
    let c = src.theta(0)?;
    let ths = c.sep.theta_s.value.to_f64();
    let mut p = Panel::new("", THETA_LABEL, FORCE_LABEL);
    p.series = force_series(&c.rows, 0, AF, 0, "θₛ");
    p.lines.push(ths_line(ths));
    p.legend.push(sep_legend());
    p.markers = onset_markers(c, src.data);
    let onsets = p.markers.len();
    p.legend.push(LegendEntry::marker(
        "slip onset for μ (table \"Where rolling first fails\")",
        (0, 0, 0),
        Shape::TriangleDown,
        true,
    ));
    let top = |i: usize| c.rows.first().map_or(f64::NAN, |r| r[AF[i]]);
    let n1min = src
        .main_sep()
        .and_then(|s| Some((extra_f(s, "N1_min")?, extra_f(s, "theta_N1_min")?)))
        .map(|(v, a)| {
            format!(
                " N₁ is smallest, {}, at θ = {}: the lower cylinder stays on the floor.",
                fmt(v, 4),
                fmt(a, 4)
            )
        })
        .unwrap_or_default();
    let title = "Main case: contact forces against θ, from rest at the top".to_string();
    Some(Figure::single("main_forces_theta.svg", title, (1000, 540), p, 230).caption(format!(
        "The contact forces against the angle θ, main case, from rest at the top (the limit θ₀ → 0+, which the forces at a \
         given θ have). At the top N₁ = {} (the weight of both) and N₁₂ = {} (the upper cylinder's weight).{n1min} \
         Separation at θₛ = {}. The {onsets} black triangles mark where rolling first needs more friction than μ, for the μ of \
         the table \"Where rolling first fails\" (on F₂₁ between the cylinders, on F₁ at the floor); the onsets are angles \
         from the top, so they are marked against θ only. {}",
        fmt(top(1), 3),
        fmt(top(3), 3),
        fmt(ths, 4),
        forces_units()
    )))
}

/// The t − tₛ view: every panel cut to the last `late_window` before
/// separation, its y range fitted to what is left. Returns the window.
fn show_late(panels: &mut [Panel], times: &[(usize, &TimeCurve)]) -> f64 {
    let w = late_window(times);
    for p in panels {
        p.xrange = Some((-w, 0.0));
        p.yrange = visible_yrange(p, -w);
    }
    w
}

fn variants_kinematics(src: &Src, shift: bool) -> Option<Figure> {
    let times = &src.times;
    if times.is_empty() {
        return None;
    }
    let panel =
        |title: &str, ylabel: &str, col: usize| time_panel(title, ylabel, times, col, shift);
    let mut panels = vec![
        panel("θ", THETA_LABEL, TH),
        panel("dθ/dt", "dθ/dt  [rad/τ]", THD),
        panel("φ₁", "φ₁  [rad]", PHI1),
        panel("φ₂", "φ₂  [rad]", PHI2),
    ];
    let window = shift.then(|| show_late(&mut panels, times));
    let zero_notes: Vec<String> = panels.iter().flat_map(|p| p.notes.clone()).collect();
    let (file, title, view) = match window {
        Some(w) => (
            "variants_kinematics_ts.svg",
            format!("All contact models: θ, dθ/dt, φ₁, φ₂ against the time to separation, {}", start_text()),
            format!(
                "The same curves against t − tₛ, so that every model separates at 0; the last {} τ before separation, \
                 where the motion happens (before it θ < 0.05 rad in every model).",
                fmt(w, 1)
            ),
        ),
        None => {
            let ts_list: Vec<String> = times
                .iter()
                .map(|&(v, c)| format!("{} {}", variant_short(v), fmt(t_s(c), 3)))
                .collect();
            (
                "variants_kinematics.svg",
                format!("All contact models: θ, dθ/dt, φ₁, φ₂ against time, {}", start_text()),
                format!("Separation times tₛ: {}.", ts_list.join(", ")),
            )
        }
    };
    let zero = if zero_notes.is_empty() {
        String::new()
    } else {
        format!(
            "Curves that are identically zero are not drawn but named in their panel: {}.",
            zero_notes.join("; ")
        )
    };
    Some(Figure::new(file, title, (1200, 860), (2, 2), panels, 250).caption(format!(
        "The six contact models overlaid, {}. {view} Colour, line style (solid: rolling floor, dashed: frictionless \
         floor, dash-dot: fixed lower cylinder) and marker shape each tell the models apart, and each curve is labelled \
         floor/contact at its end. {zero} {}",
        start_text(),
        kin_units()
    )))
}

/// The x axis of a figure of forces.
#[derive(Clone, Copy, PartialEq, Eq)]
enum ForceAxis {
    Time,
    ToSeparation,
    Theta,
}

impl ForceAxis {
    /// (file, title, the start as the caption says it, x label)
    fn texts(self) -> (&'static str, String, String, &'static str) {
        match self {
            ForceAxis::Time => (
                "variants_forces_t.svg",
                format!("All contact models: forces against time, {}", start_text()),
                start_text(),
                T_LABEL,
            ),
            ForceAxis::ToSeparation => (
                "variants_forces_ts.svg",
                format!(
                    "All contact models: forces against the time to separation, {}",
                    start_text()
                ),
                format!(
                    "{}, against t − tₛ (every model separates at 0)",
                    start_text()
                ),
                TS_LABEL,
            ),
            ForceAxis::Theta => (
                "variants_forces_theta.svg",
                "All contact models: forces against θ, from rest at the top".to_string(),
                "from rest at the top (θ₀ → 0+)".to_string(),
                THETA_LABEL,
            ),
        }
    }

    /// Force `i` of every model against this axis.
    fn curves(self, src: &Src, i: usize) -> Vec<Curve> {
        match self {
            ForceAxis::Theta => src
                .thetas
                .iter()
                .map(|&(v, c)| {
                    (
                        v,
                        column(&c.rows, 0, AF[i]),
                        f64::NAN,
                        c.sep.theta_s.value.to_f64(),
                    )
                })
                .collect(),
            _ => src
                .times
                .iter()
                .map(|&(v, c)| {
                    let mut pts = column(&c.rows, T, TF[i]);
                    if self == ForceAxis::ToSeparation {
                        pts.iter_mut().for_each(|q| q.0 -= t_s(c));
                    }
                    (v, pts, t_s(c), c.sep.theta_s.value.to_f64())
                })
                .collect(),
        }
    }
}

/// One force of every model as a panel; the forces that vanish are named in
/// `omitted`.
fn force_panel(src: &Src, axis: ForceAxis, i: usize, omitted: &mut Vec<String>) -> Panel {
    let name = FORCE_NAMES[i];
    let mut p = Panel::new(name, axis.texts().3, FORCE_LABEL);
    let curves = axis.curves(src, i);
    let n = curves.len();
    for (k, (v, pts, ts, ths)) in curves.into_iter().enumerate() {
        if force_is_zero(v, i) {
            omitted.push(format!("{name} for {}", variant_short(v)));
            continue;
        }
        let ts_text = if ts.is_finite() {
            format!(", tₛ = {}", fmt(ts, 4))
        } else {
            String::new()
        };
        let end = format!(
            "{}: {name} = {} at separation (θₛ = {}{ts_text})",
            variant_name(VARIANTS[v]),
            pts.last().map_or(String::new(), |q| fmt(q.1, 4)),
            fmt(ths, 4),
        );
        let np = pts.len();
        let s = Series::new(variant_legend(v), variant_color(v), pts)
            .dashed(variant_dash(v))
            .shape(SHAPES[v])
            .end_marker(end)
            .direct(variant_short(v));
        p.series.push(stagger(s, np, k, n));
    }
    if axis == ForceAxis::ToSeparation {
        p.lines.push(sep_line(0.0, "separation".into()));
        p.legend.push(sep_legend());
    } else {
        p.legend.push(end_legend());
    }
    p
}

fn variants_forces(src: &Src, axis: ForceAxis) -> Figure {
    let mut omitted = Vec::new();
    let mut panels: Vec<Panel> = (0..FORCE_NAMES.len())
        .map(|i| force_panel(src, axis, i, &mut omitted))
        .collect();
    if axis == ForceAxis::ToSeparation {
        show_late(&mut panels, &src.times);
    }
    let (file, title, start, _) = axis.texts();
    let n12_max_end = panels.get(3).map_or(0.0, |p| {
        p.series
            .iter()
            .filter_map(|s| s.points.last().map(|q| q.1.abs()))
            .fold(0.0, f64::max)
    });
    Figure::new(file, title, (1200, 860), (2, 2), panels, 250).caption(format!(
        "F₁, N₁, F₂₁, N₁₂ for the six contact models, {start}. A force at a frictionless contact is exactly zero and is not \
         drawn ({}). With the lower cylinder fixed (dash-dot), F₁ and N₁ are the forces of its holder. Every N₁₂ curve ends \
         within {} of 0, at its own separation. Line style, marker shape and the floor/contact label at each curve's end tell \
         the models apart without colour. {}",
        omitted.join("; "),
        fmt(n12_max_end.max(1e-4), 4),
        forces_units()
    ))
}

/// " X and Y ≡ 0 here …" for the forces that vanish in variant `v`.
fn zero_forces_text(v: usize) -> String {
    let zero: Vec<&str> = (0..4)
        .filter(|&i| force_is_zero(v, i))
        .map(|i| FORCE_NAMES[i])
        .collect();
    if zero.is_empty() {
        return String::new();
    }
    format!(
        " {} ≡ 0 here (frictionless contact) and {} not drawn.",
        zero.join(" and "),
        if zero.len() > 1 { "are" } else { "is" }
    )
}

/// The end markers that coincide near 0 at θs, said in words.
fn coincide_text(v: usize, c: &ThetaCurve) -> String {
    let near: Vec<&str> = (0..4)
        .filter(|&i| !force_is_zero(v, i))
        .filter_map(|i| Some((i, c.rows.last()?[AF[i]])))
        .filter(|(_, y)| y.abs() < 0.02)
        .map(|(i, _)| FORCE_NAMES[i])
        .collect();
    if near.len() < 2 {
        return String::new();
    }
    format!(
        " At θₛ {} all end near 0; their hollow markers of different shapes overlap without hiding each other.",
        near.join(" and ")
    )
}

/// The contact forces of one model against t and against θ.
fn variant_forces(src: &Src, v: usize) -> Option<Figure> {
    let variant = VARIANTS[v];
    let (tc, ac) = (src.time(v), src.theta(v));
    if tc.is_none() && ac.is_none() {
        return None;
    }
    let mut pt = Panel::new(
        format!("against time, {}", start_text()),
        T_LABEL,
        FORCE_LABEL,
    );
    if let Some(c) = tc {
        pt.series = force_series(&c.rows, T, TF, v, "separation");
        pt.lines.push(ts_line(c, t_s(c)));
    }
    pt.legend.push(sep_legend());
    let mut pa = Panel::new("against θ, from rest at the top", THETA_LABEL, FORCE_LABEL);
    if let Some(c) = ac {
        pa.series = force_series(&c.rows, 0, AF, v, "θₛ");
        pa.lines.push(ths_line(c.sep.theta_s.value.to_f64()));
    }
    let holder = if variant.0 == Floor::Fixed {
        " F₁ and N₁ are the forces of the holder that keeps cylinder 1 still."
    } else {
        ""
    };
    let coincide = ac.map(|c| coincide_text(v, c)).unwrap_or_default();
    let file = format!("variant_{}.svg", variant_stem(variant));
    let title = format!("{}: contact forces", variant_name(variant));
    Some(Figure::new(&file, title, (1300, 540), (1, 2), vec![pt, pa], 170).caption(format!(
        "Contact forces for {} ({}), against time {} and against θ from rest at the top.{}{holder}{coincide} {}",
        variant_name(variant),
        super::data::paper_ref(variant),
        start_text(),
        zero_forces_text(v),
        forces_units()
    )))
}

/// y at `x` on a polyline by linear interpolation.
fn interp(pts: &[(f64, f64)], x: f64) -> Option<f64> {
    pts.windows(2).find_map(|w| {
        let (a, b) = (w[0], w[1]);
        if (a.0 <= x && x <= b.0) && b.0 > a.0 {
            Some(a.1 + (b.1 - a.1) * (x - a.0) / (b.0 - a.0))
        } else {
            None
        }
    })
}

/// How much time before separation the t − tₛ views show: from where θ first
/// exceeds 0.05 rad in the slowest model, rounded up to half a τ.
fn late_window(times: &[(usize, &TimeCurve)]) -> f64 {
    let w = times
        .iter()
        .filter_map(|&(_, c)| {
            let ts = t_s(c);
            c.rows.iter().find(|r| r[TH] > 0.05).map(|r| ts - r[T])
        })
        .fold(0.5, f64::max);
    (w * 2.0).ceil() / 2.0
}

/// A y range that fits the points with x ≥ `from`, padded to whole ticks
/// (None: from all the data).
fn visible_yrange(p: &Panel, from: f64) -> Option<(f64, f64)> {
    let ys: Vec<f64> = p
        .series
        .iter()
        .flat_map(|s| s.points.iter())
        .filter(|q| q.0 >= from)
        .map(|q| q.1)
        .collect();
    if ys.is_empty() {
        return None;
    }
    let lo = ys.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = ys.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let span = (hi - lo).max(1e-3);
    let (_, step) = nice_ticks(lo, hi + 1e-3 * span, 6);
    Some(((lo / step).floor() * step, (hi / step).ceil() * step))
}

/// The friction coefficients rolling needs, with the μ levels of the table
/// "Where rolling first fails" and their onsets.
fn friction_needed(c: &ThetaCurve, data: &Data, main_sep: Option<&Separation>) -> Figure {
    let ths = c.sep.theta_s.value.to_f64();
    let mut p = Panel::new("", THETA_LABEL, "friction coefficient needed, |F|/N");
    let floor = column(&c.rows, 0, MU_FLOOR);
    let cont = column(&c.rows, 0, MU_CONTACT);
    let n = floor.len();
    let s_floor =
        Series::new("|F₁|/N₁: at the floor", PALETTE[0], floor.clone()).shape(Shape::Circle);
    let s_cont = Series::new("|F₂₁|/N₁₂: between the cylinders", PALETTE[1], cont)
        .dashed(Dash::Dashed)
        .shape(Shape::Square);
    p.series = vec![stagger(s_floor, n, 0, 2), stagger(s_cont, n, 1, 2)];
    p.lines.push(sep_line(
        ths,
        format!("θₛ = {} (|F₂₁|/N₁₂ → ∞)", fmt(ths, 4)),
    ));
    p.lines.extend(MU_VALUES.iter().map(|mu| RefLine {
        at: text_f64(mu),
        vertical: false,
        color: (120, 120, 120),
        dash: Dash::Dotted,
        label: format!("μ = {mu}"),
    }));
    let (contact_onsets, floor_onsets) = mu_onsets(&mut p, data);
    // the floor's maximum, verified
    let fmax = main_sep.and_then(|s| {
        Some((
            extra_f(s, "mu_floor_max")?,
            extra_f(s, "theta_mu_floor_max")?,
        ))
    });
    if let Some((m, a)) = fmax {
        let title = format!(
            "largest |F₁|/N₁ before separation: {} at θ = {}",
            fmt(m, 4),
            fmt(a, 4)
        );
        p.markers.push(Marker::shaped(
            Shape::Diamond,
            (a, m),
            PALETTE[0],
            title,
            Some(format!("max {}", fmt(m, 4))),
        ));
    }
    p.legend.push(LegendEntry::line(
        "separation θₛ (N₁₂ = 0)",
        SEP_COLOR,
        Dash::Dotted,
    ));
    p.yrange = Some((0.0, 1.05));
    p.xrange = Some((0.0, (ths * 10.0).ceil() / 10.0 + 0.05));
    // caption claims from the data
    let (f1_sign, f1_changes) = sign_text(&column(&c.rows, 0, AF[0])[1..], "θ");
    let floor_text = match fmax {
        Some((m, a)) => format!(
            "The floor needs at most |F₁|/N₁ = {} (at θ = {}, diamond; a verified extremum), so any μ above it keeps the floor rolling \
             to separation; F₁ {f1_sign}{}",
            fmt(m, 4),
            fmt(a, 4),
            if f1_changes { ", where |F₁|/N₁ passes through zero" } else { "" }
        ),
        None => format!("F₁ {f1_sign}"),
    };
    let floor_end = floor.last().map_or(f64::NAN, |q| q.1);
    let at_floor = if floor_onsets.is_empty() {
        String::new()
    } else {
        format!("; at the floor at θ = {}", floor_onsets.join(", "))
    };
    let title = "Main case: friction coefficient needed, from rest at the top".to_string();
    Figure::single("main_friction.svg", title, (1000, 560), p, 250).caption(format!(
        "The friction coefficients that rolling without slipping needs: |F₁|/N₁ at the floor and |F₂₁|/N₁₂ between the cylinders, \
         main case, from rest at the top. {floor_text}; at θₛ it is {}. F₂₁ stays finite while N₁₂ → 0, so the coefficient needed \
         between the cylinders grows without bound as θ → θₛ: for any finite μ the upper cylinder slips before it separates. \
         Dotted levels: the μ of the table \"Where rolling first fails\"; triangles: where each level is first exceeded \
         (between the cylinders at θ = {}{at_floor}). The axis is cut at μ = 1.05.",
        fmt(floor_end, 4),
        contact_onsets.join(", "),
    ))
}

/// The slip onsets of the μ levels as markers on `p` (and their legend
/// entries); returns the onsets between the cylinders and at the floor as
/// text ("μ: θ").
fn mu_onsets(p: &mut Panel, data: &Data) -> (Vec<String>, Vec<String>) {
    // (verified angle, colour, marker, what starts to slip, legend)
    let kinds = [
        (
            "theta_slip_contact",
            PALETTE[1],
            Shape::TriangleDown,
            "the contact between the cylinders",
            "slip onset between the cylinders, at μ",
        ),
        (
            "theta_slip_floor",
            PALETTE[0],
            Shape::Triangle,
            "the floor",
            "slip onset at the floor, at μ",
        ),
    ];
    let mut onsets = [Vec::new(), Vec::new()];
    for (mu, r) in MU_VALUES.iter().zip(&data.mu) {
        let Ok(s) = r else { continue };
        for (k, &(name, color, shape, what, _)) in kinds.iter().enumerate() {
            if let Some(a) = extra_f(s, name) {
                onsets[k].push(format!("{mu}: {}", fmt(a, 3)));
                let title = format!("μ = {mu}: {what} starts to slip at θ = {}", fmt(a, 4));
                p.markers
                    .push(Marker::shaped(shape, (a, text_f64(mu)), color, title, None));
            }
        }
    }
    for (k, &(_, color, shape, _, legend)) in kinds.iter().enumerate() {
        // the contact always slips before separation; the floor may not
        if k == 0 || !onsets[k].is_empty() {
            p.legend
                .push(LegendEntry::marker(legend, color, shape, true));
        }
    }
    let [contact, floor] = onsets;
    (contact, floor)
}

fn plane_value(data: &Data, floor: FloorKey, ratio: &str, k2: &str, digits: u32) -> Option<f64> {
    let key = PlaneKey {
        floor,
        ratio: ratio.to_string(),
        k2: k2.to_string(),
        digits,
    };
    match data.plane.get(&key) {
        Some(Ok(v)) => Some(v.value.to_f64()),
        _ => None,
    }
}

fn fixed_closed_form(k2: f64) -> f64 {
    (2.0 / (3.0 + k2)).acos()
}

const K2_DEF: &str = "k₂ = I₂/(m₂r₂²)";

const PLANE_TEXT: &str = "Both contacts rolling, from rest at the top; m₁ = r₁ = r₂ = g = 1, k₁ = 1/2 (a solid lower cylinder); \
                          k₂ = I₂/(m₂r₂²) is the upper cylinder's moment of inertia in units of m₂r₂² (0: a point mass on the rim's \
                          axis, 1/2: solid, 1: thin-walled tube, 2: a bobbin).";

/// Curve `j` of `of` of a family over the parameter plane: labelled at its
/// end, with staggered markers.
fn family_series(label: String, j: usize, of: usize, pts: Vec<(f64, f64)>) -> Series {
    let n = pts.len();
    let s = Series::new(label.clone(), PALETTE[j], pts)
        .shape(SHAPES[j])
        .direct(label);
    stagger(s, n, j, of)
}

fn plane_figures(data: &Data, cfg: &Config) -> Vec<Figure> {
    let flat = flattest_k2(data, cfg);
    let mut figs = vec![plane_ratio(data, cfg), plane_k2(data, cfg, flat.as_ref())];
    figs.extend(heatmap(data, cfg, flat.as_ref(), PLANE_TEXT));
    figs
}

/// θs against m2/m1 for several k2, with the fixed-lower limits.
fn plane_ratio(data: &Data, cfg: &Config) -> Figure {
    let pd = cfg.plot_digits;
    let ratios = log_grid(cfg.ratio_range.0, cfg.ratio_range.1, cfg.ratio_per_decade);
    let xr = (text_f64(&ratios[0]), text_f64(&ratios[ratios.len() - 1]));
    let mut p = Panel::new("", "m₂/m₁  (log scale)", "θₛ  [rad]");
    p.xscale = Scale::Log;
    p.xrange = Some(xr);
    for (j, k2) in PLANE_K2.iter().enumerate() {
        let pts: Vec<(f64, f64)> = ratios
            .iter()
            .filter_map(|r| Some((text_f64(r), plane_value(data, FloorKey::Roll, r, k2, pd)?)))
            .collect();
        p.series
            .push(family_series(format!("k₂ = {k2}"), j, PLANE_K2.len(), pts));
        let lim = fixed_closed_form(text_f64(k2));
        p.series
            .push(Series::new("", PALETTE[j], vec![(xr.0, lim), (xr.1, lim)]).dashed(Dash::Dashed));
    }
    p.legend.push(LegendEntry::line(
        "dashed, same colour: fixed lower cylinder, arccos(2/(3 + k₂))",
        PALETTE[6],
        Dash::Dashed,
    ));
    let title = "Separation angle over the mass ratio, for several k₂".to_string();
    Figure::single("plane_ratio.svg", title, (1100, 600), p, 230).caption(format!(
        "θₛ against m₂/m₁ from {} to {} (log scale) for k₂ = {}, each curve labelled at its end. Dashed, in the same colour: the \
         fixed-lower-cylinder value arccos(2/(3 + k₂)) of eq. (36), the limit m₂/m₁ → 0. {PLANE_TEXT}",
        ratios[0],
        ratios[ratios.len() - 1],
        PLANE_K2.join(", ")
    ))
}

/// θs against k2 for several m2/m1, with the fixed-lower curve.
fn plane_k2(data: &Data, cfg: &Config, flat: Option<&Flat>) -> Figure {
    let pd = cfg.plot_digits;
    let ks = k2_grid(cfg.k2_steps);
    let mut p = Panel::new("", K2_DEF, "θₛ  [rad]");
    p.xrange = Some((0.0, 2.0));
    for (j, r) in PLANE_TABLE_RATIOS.iter().enumerate() {
        let pts: Vec<(f64, f64)> = ks
            .iter()
            .filter_map(|k| Some((text_f64(k), plane_value(data, FloorKey::Roll, r, k, pd)?)))
            .collect();
        p.series.push(family_series(
            format!("m₂/m₁ = {r}"),
            j,
            PLANE_TABLE_RATIOS.len(),
            pts,
        ));
    }
    let curve: Vec<(f64, f64)> = (0..=200)
        .map(|i| {
            let k = 2.0 * f64::from(i) / 200.0;
            (k, fixed_closed_form(k))
        })
        .collect();
    let label = "fixed lower cylinder: arccos(2/(3 + k₂))";
    p.series
        .push(Series::new(label, PALETTE[6], curve).dashed(Dash::Dashed));
    let white = (255, 255, 255);
    for k in &ks {
        if let Some(v) = plane_value(data, FloorKey::Fixed, "1", k, pd) {
            let title = format!("oracle, fixed lower cylinder, k₂ = {k}: θₛ = {}", fmt(v, 5));
            p.markers.push(Marker::new((text_f64(k), v), white, title));
        }
    }
    p.legend.push(LegendEntry::marker(
        "oracle, fixed lower cylinder",
        white,
        Shape::Circle,
        true,
    ));
    let cross = flat
        .map(|f| format!(" The curves come closest together near k₂ ≈ {} (θₛ ≈ {}°): there θₛ hardly depends on m₂/m₁ (see the heat map).", fmt(f.k2, 2), fmt(f.mean, 1)))
        .unwrap_or_default();
    let title = "Separation angle over k₂, for several mass ratios".to_string();
    Figure::single("plane_k2.svg", title, (1100, 600), p, 230).caption(format!(
        "θₛ against k₂ for m₂/m₁ = {}, each curve labelled at its end. Black dashed: the closed form arccos(2/(3 + k₂)) for a \
         fixed lower cylinder (eq. 36); the white circles on it are the oracle's values for a fixed lower cylinder.{cross} {PLANE_TEXT}",
        PLANE_TABLE_RATIOS.join(", ")
    ))
}

/// Where θs depends least on the mass ratio: the k₂ of the heat map's rows
/// with the smallest spread of θs over m₂/m₁ (refined by a parabola through
/// the neighbouring rows).
pub struct Flat {
    /// k₂ of the smallest spread.
    pub k2: f64,
    /// The spread there, in degrees (at the nearest row).
    pub spread: f64,
    /// The mean θs there, in degrees.
    pub mean: f64,
    /// The grid row of the smallest spread.
    pub row: f64,
}

fn heat_grid(data: &Data, cfg: &Config) -> (Vec<String>, Vec<String>, Vec<Vec<f64>>) {
    let hr = log_grid(
        cfg.heat_ratio_range.0,
        cfg.heat_ratio_range.1,
        cfg.heat_per_decade,
    );
    let hk = k2_grid(cfg.heat_k2_steps);
    let z: Vec<Vec<f64>> = hk
        .iter()
        .map(|k| {
            hr.iter()
                .map(|r| {
                    plane_value(data, FloorKey::Roll, r, k, cfg.plot_digits)
                        .map(|v| v.to_degrees())
                        .unwrap_or(f64::NAN)
                })
                .collect()
        })
        .collect();
    (hr, hk, z)
}

fn flattest_k2(data: &Data, cfg: &Config) -> Option<Flat> {
    let (hr, hk, z) = heat_grid(data, cfg);
    // the spread of θs over the mass ratios of the curves θs(k2) (0.1 to 10)
    let cols: Vec<usize> = hr
        .iter()
        .enumerate()
        .filter(|(_, r)| {
            let v = text_f64(r);
            (0.1 * (1.0 - 1e-9)..=10.0 * (1.0 + 1e-9)).contains(&v)
        })
        .map(|(i, _)| i)
        .collect();
    let spread: Vec<f64> = z
        .iter()
        .map(|row| {
            let f: Vec<f64> = cols
                .iter()
                .map(|&i| row[i])
                .filter(|v| v.is_finite())
                .collect();
            if f.len() < 2 {
                return f64::NAN;
            }
            f.iter().copied().fold(f64::NEG_INFINITY, f64::max)
                - f.iter().copied().fold(f64::INFINITY, f64::min)
        })
        .collect();
    let (j, &s) = spread
        .iter()
        .enumerate()
        .filter(|(_, v)| v.is_finite())
        .min_by(|a, b| a.1.total_cmp(b.1))?;
    let ks: Vec<f64> = hk.iter().map(|k| text_f64(k)).collect();
    // the row itself: the curves come closest there (they need not meet in one point)
    let k2 = ks[j];
    let f: Vec<f64> = cols
        .iter()
        .map(|&i| z[j][i])
        .filter(|v| v.is_finite())
        .collect();
    let mean = f.iter().sum::<f64>() / f.len().max(1) as f64;
    Some(Flat {
        k2,
        spread: s,
        mean,
        row: ks[j],
    })
}

/// A smooth raster of the grid `z` over nodes `xs` × `ys`, interpolated
/// bilinearly and coloured over [lo, hi].
fn heat_raster(xs: &[f64], ys: &[f64], z: &[Vec<f64>], lo: f64, hi: f64) -> Raster {
    let (w, h) = (200usize, 150usize);
    let bil = |u: f64, v: f64| -> f64 {
        let fi = u * (xs.len() - 1) as f64;
        let fj = v * (ys.len() - 1) as f64;
        let i = (fi.floor() as usize).min(xs.len() - 2);
        let j = (fj.floor() as usize).min(ys.len() - 2);
        let (a, b) = (fi - i as f64, fj - j as f64);
        let z00 = z[j][i];
        let z10 = z[j][i + 1];
        let z01 = z[j + 1][i];
        let z11 = z[j + 1][i + 1];
        (1.0 - a) * (1.0 - b) * z00 + a * (1.0 - b) * z10 + (1.0 - a) * b * z01 + a * b * z11
    };
    let mut pixels = Vec::with_capacity(w * h);
    for r in 0..h {
        let v = 1.0 - (r as f64 + 0.5) / h as f64;
        for c in 0..w {
            let u = (c as f64 + 0.5) / w as f64;
            let val = bil(u, v);
            pixels.push(if val.is_finite() {
                viridis((val - lo) / (hi - lo))
            } else {
                (200, 200, 200)
            });
        }
    }
    Raster {
        x: (xs[0], xs[xs.len() - 1]),
        y: (ys[0], ys[ys.len() - 1]),
        w,
        h,
        pixels,
    }
}

/// A contour line that crosses the whole range of mass ratios of the curves
/// θs(k2) (0.1 to 10): its level, its k2 range there, and its ends over the
/// whole plot (log10 ratio, k2).
type Crossing = (f64, f64, f64, Option<(f64, f64)>, Option<(f64, f64)>);

/// The contour lines at `levels` as series and labels on `p` (x in log10);
/// returns the lines that cross 0.1 to 10.
fn heat_contours(
    p: &mut Panel,
    xs: &[f64],
    ys: &[f64],
    z: &[Vec<f64>],
    levels: &[f64],
) -> Vec<Crossing> {
    let mut crossing = Vec::new();
    for &level in levels {
        for line in chain(&contour(xs, ys, z, level)) {
            let pts: Vec<(f64, f64)> = line.iter().map(|&(x, y)| (10f64.powf(x), y)).collect();
            let mid: Vec<f64> = line
                .iter()
                .filter(|q| (-1.0 - 1e-9..=1.0 + 1e-9).contains(&q.0))
                .map(|q| q.1)
                .collect();
            let kmin = mid.iter().copied().fold(f64::INFINITY, f64::min);
            let kmax = mid.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            let lo_end = line.iter().min_by(|a, b| a.0.total_cmp(&b.0)).copied();
            let hi_end = line.iter().max_by(|a, b| a.0.total_cmp(&b.0)).copied();
            let covers =
                line.iter().any(|q| q.0 <= -1.0 + 1e-9) && line.iter().any(|q| q.0 >= 1.0 - 1e-9);
            if covers {
                crossing.push((level, kmin, kmax, lo_end, hi_end));
            }
            if line.len() >= 4 {
                // the label at the point of the line nearest to its middle in x
                let mid = line.iter().map(|q| q.0).sum::<f64>() / line.len() as f64;
                let at = line
                    .iter()
                    .min_by(|a, b| (a.0 - mid).abs().total_cmp(&(b.0 - mid).abs()))
                    .copied()
                    .unwrap_or(line[0]);
                p.labels.push(Label {
                    at: (10f64.powf(at.0), at.1),
                    text: format!("{level:.0}°"),
                });
            }
            let mut s = Series::new(format!("θₛ = {level:.0}° contour"), (0, 0, 0), pts);
            s.width = 1.0;
            p.series.push(s);
        }
    }
    crossing
}

/// The caption's sentences on the flattest contour and the flattest row.
fn flat_text(crossing: &[Crossing], flat: Option<&Flat>) -> String {
    let flattest = crossing
        .iter()
        .min_by(|a, b| (a.2 - a.1).total_cmp(&(b.2 - b.1)));
    let contour_text = flattest
        .filter(|f| f.2 - f.1 < 0.05)
        .map(|&(l, a, b, lo, hi)| {
            let ends = match (lo, hi) {
                (Some(p), Some(q)) => format!(
                    " (over the whole plot it runs from k₂ = {} at m₂/m₁ = {} to {} at {})",
                    fmt(p.1, 3),
                    super::plot::csv_num(10f64.powf(p.0), 3),
                    fmt(q.1, 3),
                    super::plot::csv_num(10f64.powf(q.0), 3)
                ),
                _ => String::new(),
            };
            format!(
                " The {l:.0}° contour is almost flat: for m₂/m₁ from 0.1 to 10 it stays between k₂ = {} and {}{ends}, so there θₛ \
                 hardly depends on the mass ratio.",
                fmt(a, 3),
                fmt(b, 3)
            )
        })
        .unwrap_or_default();
    match flat {
        Some(f) => format!(
            "{contour_text} Over m₂/m₁ from 0.1 to 10, θₛ varies least on the row k₂ = {} of the grid (by {}°, around {}°): the curves \
             of θₛ against k₂ for different m₂/m₁ come closest together there (figure above).",
            fmt(f.row, 3),
            fmt(f.spread, 2),
            fmt(f.mean, 1)
        ),
        None => contour_text,
    }
}

/// θs over (m₂/m₁, k₂): a smooth raster interpolated bilinearly between the
/// oracle's nodes, labelled contours, the colour scale fitted to the data.
fn heatmap(data: &Data, cfg: &Config, flat: Option<&Flat>, plane_text: &str) -> Option<Figure> {
    let (hr, hk, z) = heat_grid(data, cfg);
    let xs: Vec<f64> = hr.iter().map(|r| text_f64(r).log10()).collect();
    let ys: Vec<f64> = hk.iter().map(|k| text_f64(k)).collect();
    let finite = z.iter().flatten().copied().filter(|v| v.is_finite());
    let zlo = finite.clone().fold(f64::INFINITY, f64::min);
    let zhi = finite.fold(f64::NEG_INFINITY, f64::max);
    if !(zlo.is_finite() && zhi.is_finite() && xs.len() > 1 && ys.len() > 1) {
        return None;
    }
    let (lo, hi) = (zlo, zhi.max(zlo + 1e-9));
    // contour levels every 5° inside the data
    let step = 5.0;
    let levels: Vec<f64> = ((lo / step).ceil() as i64..=(hi / step).floor() as i64)
        .map(|i| i as f64 * step)
        .collect();
    let mut p = Panel::new("", "m₂/m₁  (log scale)", K2_DEF);
    p.xscale = Scale::Log;
    p.xrange = Some((10f64.powf(xs[0]), 10f64.powf(xs[xs.len() - 1])));
    p.yrange = Some((ys[0], ys[ys.len() - 1]));
    p.raster = Some(heat_raster(&xs, &ys, &z, lo, hi));
    let crossing = heat_contours(&mut p, &xs, &ys, &z, &levels);
    let flat_text = flat_text(&crossing, flat);
    let mut csv = String::from("m2_over_m1,k2,theta_s_deg\n");
    for (j, k) in hk.iter().enumerate() {
        for (i, r) in hr.iter().enumerate() {
            let v = super::plot::csv_num(z[j][i], cfg.plot_digits as usize);
            csv.push_str(&format!("{r},{k},{v}\n"));
        }
    }
    let title = "Separation angle θₛ over the parameter plane".to_string();
    let mut fig = Figure::single("plane_heatmap.svg", title, (1000, 660), p, 130);
    fig.colorbar = Some(ColorBar {
        label: "θₛ [deg]".into(),
        range: (lo, hi),
        marks: levels.iter().map(|l| (*l, String::new())).collect(),
    });
    fig.csv = Some(csv);
    Some(fig.caption(format!(
        "θₛ in degrees (colour; the scale spans the data, {}° to {}°) over m₂/m₁ from {} to {} (log scale, the range of the curves \
         above) and k₂ from {} to {}, with labelled contours every {step:.0}°. {} × {} oracle values, interpolated bilinearly between \
         them for the colour and the contours.{flat_text} {plane_text}",
        fmt(zlo, 1),
        fmt(zhi, 1),
        hr[0],
        hr[hr.len() - 1],
        hk[0],
        hk[hk.len() - 1],
        hr.len(),
        hk.len()
    )))
}
