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

fn ok_time(data: &Data) -> Vec<(usize, &TimeCurve)> {
    data.time
        .iter()
        .enumerate()
        .filter_map(|(v, r)| r.as_ref().ok().map(|c| (v, c)))
        .collect()
}

fn ok_theta(data: &Data) -> Vec<(usize, &ThetaCurve)> {
    data.theta
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

/// All figures, in page order.
pub fn figures(data: &Data, cfg: &Config) -> Vec<Figure> {
    let mut figs = vec![super::diagram::figure()];
    let times = ok_time(data);
    let thetas = ok_theta(data);
    let main_t: Vec<(usize, &TimeCurve)> = times.iter().copied().filter(|(v, _)| *v == 0).collect();
    let main_a: Vec<(usize, &ThetaCurve)> =
        thetas.iter().copied().filter(|(v, _)| *v == 0).collect();
    let cyl = "Identical solid cylinders, m₁ = m₂ = r₁ = r₂ = g = 1, k₁ = k₂ = 1/2";
    let forces_units = format!("{cyl}; time unit {TAU}, forces in units of m₁g.");
    let kin_units = format!("{cyl}; time unit {TAU}.");
    let main_sep = data
        .sep
        .first()
        .and_then(|s| s.first())
        .and_then(|r| r.as_ref().ok());

    // --- main case: kinematics
    if let Some(&(_, c)) = main_t.first() {
        let panels = vec![
            time_panel(
                "θ: line of centres from the vertical",
                THETA_LABEL,
                &main_t,
                TH,
                false,
            ),
            time_panel("dθ/dt", "dθ/dt  [rad/τ]", &main_t, THD, false),
            time_panel(
                "φ₁: clockwise rotation of cylinder 1",
                "φ₁  [rad]",
                &main_t,
                PHI1,
                false,
            ),
            time_panel(
                "φ₂: the paper's angle of cylinder 2",
                "φ₂  [rad]",
                &main_t,
                PHI2,
                false,
            ),
        ];
        let (phi1_sign, _) = sign_text(&column(&c.rows, T, PHI1)[1..], "t");
        let ts = t_s(c);
        let phi1dot = extra_f(&c.sep, "theta_phi1dot_zero");
        let ths = c.sep.theta_s.value.to_f64();
        let dot_text = match phi1dot {
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
        };
        let after = extra_f(&c.sep, "theta_phi1_zero_after_separation")
            .map(|a| format!(" (the formulas continued past separation would change its sign only at θ = {}, a property of the formulas, not of the motion)", fmt(a, 4)))
            .unwrap_or_default();
        let t_half = c
            .rows
            .iter()
            .find(|r| r[TH] > 0.1)
            .map_or(f64::NAN, |r| r[T]);
        figs.push(
            Figure::new("main_kinematics.svg", format!("Main case (both contacts rolling), {}", start_text()), (1200, 820), (2, 2), panels, 210)
                .caption(format!(
                    "θ, dθ/dt, φ₁ and φ₂ against time for the paper's main case (§2), {}; separation (N₁₂ = 0) at tₛ = {} \
                     (dotted line; hover a marker for the values). The start is slow: θ stays below 0.1 rad until t ≈ {} of {}; \
                     the plots against t − tₛ under \"All contact models\" show the last part larger. φ₁ {phi1_sign}{after}; {dot_text}. {kin_units}",
                    start_text(),
                    fmt(ts, 4),
                    fmt(t_half, 2),
                    fmt(ts, 2),
                )),
        );
    }

    // --- main case: forces against t and θ
    if let Some(&(_, c)) = main_t.first() {
        let mut p = Panel::new("", T_LABEL, FORCE_LABEL);
        p.series = force_series(&c.rows, T, TF, 0, "separation");
        p.lines
            .push(sep_line(t_s(c), format!("tₛ = {}", fmt(t_s(c), 4))));
        p.legend.push(sep_legend());
        let f21 = column(&c.rows, T, TF[2]);
        let (f21_sign, _) = sign_text(&f21[1..], "t");
        figs.push(
            Figure::single("main_forces_t.svg", format!("Main case: contact forces against time, {}", start_text()), (1000, 520), p, 230)
                .caption(format!(
                    "The four contact forces against time, main case, {}. {}; {}; {}; {} (see the sign-convention diagram). \
                     F₂₁ {f21_sign}: the friction on cylinder 2 points along (−cos θ, sin θ), back up the slope. \
                     N₁₂ reaches 0 at separation, tₛ = {}. {forces_units}",
                    start_text(),
                    FORCE_LONG[0],
                    FORCE_LONG[1],
                    FORCE_LONG[2],
                    FORCE_LONG[3],
                    fmt(t_s(c), 4)
                )),
        );
    }
    if let Some(&(_, c)) = main_a.first() {
        let ths = c.sep.theta_s.value.to_f64();
        let mut p = Panel::new("", THETA_LABEL, FORCE_LABEL);
        p.series = force_series(&c.rows, 0, AF, 0, "θₛ");
        p.lines.push(sep_line(ths, format!("θₛ = {}", fmt(ths, 4))));
        p.legend.push(sep_legend());
        // slip onsets of the table "Where rolling first fails", on F21 and F1
        let f21 = column(&c.rows, 0, AF[2]);
        let f1 = column(&c.rows, 0, AF[0]);
        let mut onsets = 0;
        for (mu, r) in MU_VALUES.iter().zip(&data.mu) {
            let Ok(s) = r else { continue };
            for (name, curve, on) in [
                ("theta_slip_contact", &f21, "between the cylinders"),
                ("theta_slip_floor", &f1, "at the floor"),
            ] {
                if let Some(a) = extra_f(s, name) {
                    if let Some(y) = interp(curve, a) {
                        onsets += 1;
                        p.markers.push(Marker {
                            at: (a, y),
                            color: (0, 0, 0),
                            shape: Shape::TriangleDown,
                            filled: true,
                            title: format!(
                                "μ = {mu}: rolling {on} first needs more friction than μ at θ = {}",
                                fmt(a, 4)
                            ),
                            label: Some(format!("μ={mu}")),
                        });
                    }
                }
            }
        }
        p.legend.push(LegendEntry {
            label: "slip onset for μ (table \"Where rolling first fails\")".into(),
            color: (0, 0, 0),
            dash: None,
            shape: Some(Shape::TriangleDown),
            filled: true,
        });
        let n1_top = c.rows.first().map_or(f64::NAN, |r| r[AF[1]]);
        let n12_top = c.rows.first().map_or(f64::NAN, |r| r[AF[3]]);
        let n1min = main_sep
            .and_then(|s| Some((extra_f(s, "N1_min")?, extra_f(s, "theta_N1_min")?)))
            .map(|(v, a)| {
                format!(
                    " N₁ is smallest, {}, at θ = {}: the lower cylinder stays on the floor.",
                    fmt(v, 4),
                    fmt(a, 4)
                )
            })
            .unwrap_or_default();
        figs.push(
            Figure::single("main_forces_theta.svg", "Main case: contact forces against θ, from rest at the top".into(), (1000, 540), p, 230)
                .caption(format!(
                    "The contact forces against the angle θ, main case, from rest at the top (the limit θ₀ → 0+, which the forces at a \
                     given θ have). At the top N₁ = {} (the weight of both) and N₁₂ = {} (the upper cylinder's weight).{n1min} \
                     Separation at θₛ = {}. The {onsets} black triangles mark where rolling first needs more friction than μ, for the μ of \
                     the table \"Where rolling first fails\" (on F₂₁ between the cylinders, on F₁ at the floor); the onsets are angles \
                     from the top, so they are marked against θ only. {forces_units}",
                    fmt(n1_top, 3),
                    fmt(n12_top, 3),
                    fmt(ths, 4)
                )),
        );

        figs.push(friction_needed(c, data, main_sep));
    }

    // --- all contact models overlaid: kinematics, against t and against t − ts
    if !times.is_empty() {
        for shift in [false, true] {
            let panels = vec![
                time_panel("θ", THETA_LABEL, &times, TH, shift),
                time_panel("dθ/dt", "dθ/dt  [rad/τ]", &times, THD, shift),
                time_panel("φ₁", "φ₁  [rad]", &times, PHI1, shift),
                time_panel("φ₂", "φ₂  [rad]", &times, PHI2, shift),
            ];
            let mut panels = panels;
            let window = if shift {
                Some(late_window(&times))
            } else {
                None
            };
            if let Some(w) = window {
                for p in &mut panels {
                    p.xrange = Some((-w, 0.0));
                    p.yrange = visible_yrange(p, -w);
                }
            }
            let zero_notes: Vec<String> = panels.iter().flat_map(|p| p.notes.clone()).collect();
            let ts_list: Vec<String> = times
                .iter()
                .map(|&(v, c)| format!("{} {}", variant_short(v), fmt(t_s(c), 3)))
                .collect();
            let (file, title, view) = if shift {
                (
                    "variants_kinematics_ts.svg",
                    format!("All contact models: θ, dθ/dt, φ₁, φ₂ against the time to separation, {}", start_text()),
                    format!(
                        "The same curves against t − tₛ, so that every model separates at 0; the last {} τ before separation, \
                         where the motion happens (before it θ < 0.05 rad in every model).",
                        fmt(window.unwrap_or(0.0), 1)
                    ),
                )
            } else {
                (
                    "variants_kinematics.svg",
                    format!(
                        "All contact models: θ, dθ/dt, φ₁, φ₂ against time, {}",
                        start_text()
                    ),
                    format!("Separation times tₛ: {}.", ts_list.join(", ")),
                )
            };
            figs.push(
                Figure::new(file, title, (1200, 860), (2, 2), panels, 250).caption(format!(
                    "The six contact models overlaid, {}. {view} Colour, line style (solid: rolling floor, dashed: frictionless \
                     floor, dash-dot: fixed lower cylinder) and marker shape each tell the models apart, and each curve is labelled \
                     floor/contact at its end. {} {kin_units}",
                    start_text(),
                    if zero_notes.is_empty() {
                        String::new()
                    } else {
                        format!("Curves that are identically zero are not drawn but named in their panel: {}.", zero_notes.join("; "))
                    }
                )),
            );
        }
    }

    // --- all contact models overlaid: forces against t − ts and θ
    for (mode, file) in [
        (0, "variants_forces_t.svg"),
        (1, "variants_forces_ts.svg"),
        (2, "variants_forces_theta.svg"),
    ] {
        let mut panels = Vec::new();
        let mut omitted = Vec::new();
        let xlabel = [T_LABEL, TS_LABEL, THETA_LABEL][mode];
        for (i, name) in FORCE_NAMES.iter().enumerate() {
            let mut p = Panel::new(*name, xlabel, FORCE_LABEL);
            // (variant, points, tₛ, θₛ)
            let mut curves: Vec<Curve> = Vec::new();
            if mode < 2 {
                for &(v, c) in &times {
                    let mut pts = column(&c.rows, T, TF[i]);
                    if mode == 1 {
                        for q in &mut pts {
                            q.0 -= t_s(c);
                        }
                    }
                    curves.push((v, pts, t_s(c), c.sep.theta_s.value.to_f64()));
                }
            } else {
                for &(v, c) in &thetas {
                    curves.push((
                        v,
                        column(&c.rows, 0, AF[i]),
                        f64::NAN,
                        c.sep.theta_s.value.to_f64(),
                    ));
                }
            }
            let n = curves.len();
            for (k, (v, pts, ts, ths)) in curves.into_iter().enumerate() {
                if force_is_zero(v, i) {
                    omitted.push(format!("{name} for {}", variant_short(v)));
                    continue;
                }
                let end = format!(
                    "{}: {name} = {} at separation (θₛ = {}{})",
                    variant_name(VARIANTS[v]),
                    pts.last().map_or(String::new(), |q| fmt(q.1, 4)),
                    fmt(ths, 4),
                    if ts.is_finite() {
                        format!(", tₛ = {}", fmt(ts, 4))
                    } else {
                        String::new()
                    }
                );
                let np = pts.len();
                p.series.push(stagger(
                    Series::new(variant_legend(v), variant_color(v), pts)
                        .dashed(variant_dash(v))
                        .shape(SHAPES[v])
                        .end_marker(end)
                        .direct(variant_short(v)),
                    np,
                    k,
                    n,
                ));
            }
            if mode == 1 {
                p.lines.push(sep_line(0.0, "separation".into()));
                p.legend.push(sep_legend());
            } else {
                p.legend.push(end_legend());
            }
            panels.push(p);
        }
        if mode == 1 {
            let w = late_window(&times);
            for p in &mut panels {
                p.xrange = Some((-w, 0.0));
                p.yrange = visible_yrange(p, -w);
            }
        }
        let (title, start) = match mode {
            0 => (
                format!("All contact models: forces against time, {}", start_text()),
                start_text(),
            ),
            1 => (
                format!(
                    "All contact models: forces against the time to separation, {}",
                    start_text()
                ),
                format!(
                    "{}, against t − tₛ (every model separates at 0)",
                    start_text()
                ),
            ),
            _ => (
                "All contact models: forces against θ, from rest at the top".to_string(),
                "from rest at the top (θ₀ → 0+)".to_string(),
            ),
        };
        let n12_end: Vec<f64> = panels
            .get(3)
            .map(|p| {
                p.series
                    .iter()
                    .filter_map(|s| s.points.last().map(|q| q.1))
                    .collect()
            })
            .unwrap_or_default();
        let n12_max_end = n12_end.iter().map(|v| v.abs()).fold(0.0, f64::max);
        figs.push(
            Figure::new(file, title, (1200, 860), (2, 2), panels, 250).caption(format!(
                "F₁, N₁, F₂₁, N₁₂ for the six contact models, {start}. A force at a frictionless contact is exactly zero and is not \
                 drawn ({}). With the lower cylinder fixed (dash-dot), F₁ and N₁ are the forces of its holder. Every N₁₂ curve ends \
                 within {} of 0, at its own separation. Line style, marker shape and the floor/contact label at each curve's end tell \
                 the models apart without colour. {forces_units}",
                omitted.join("; "),
                fmt(n12_max_end.max(1e-4), 4)
            )),
        );
    }

    // --- one figure per contact model: forces against t and θ
    for (v, variant) in VARIANTS.iter().enumerate() {
        let tc = times.iter().find(|(w, _)| *w == v).map(|x| x.1);
        let ac = thetas.iter().find(|(w, _)| *w == v).map(|x| x.1);
        if tc.is_none() && ac.is_none() {
            continue;
        }
        let mut panels = Vec::new();
        let mut p = Panel::new(
            format!("against time, {}", start_text()),
            T_LABEL,
            FORCE_LABEL,
        );
        if let Some(c) = tc {
            p.series = force_series(&c.rows, T, TF, v, "separation");
            p.lines
                .push(sep_line(t_s(c), format!("tₛ = {}", fmt(t_s(c), 4))));
        }
        p.legend.push(sep_legend());
        panels.push(p);
        let mut p = Panel::new("against θ, from rest at the top", THETA_LABEL, FORCE_LABEL);
        if let Some(c) = ac {
            p.series = force_series(&c.rows, 0, AF, v, "θₛ");
            let ths = c.sep.theta_s.value.to_f64();
            p.lines.push(sep_line(ths, format!("θₛ = {}", fmt(ths, 4))));
        }
        panels.push(p);
        let zero: Vec<&str> = (0..4)
            .filter(|&i| force_is_zero(v, i))
            .map(|i| FORCE_NAMES[i])
            .collect();
        let zero_text = if zero.is_empty() {
            String::new()
        } else {
            format!(
                " {} ≡ 0 here (frictionless contact) and {} not drawn.",
                zero.join(" and "),
                if zero.len() > 1 { "are" } else { "is" }
            )
        };
        let holder = if variant.0 == Floor::Fixed {
            " F₁ and N₁ are the forces of the holder that keeps cylinder 1 still."
        } else {
            ""
        };
        // coinciding end markers, said in words
        let mut coincide = String::new();
        if let Some(c) = ac {
            let ends: Vec<(usize, f64)> = (0..4)
                .filter(|&i| !force_is_zero(v, i))
                .filter_map(|i| Some((i, c.rows.last()?[AF[i]])))
                .collect();
            let near: Vec<&str> = ends
                .iter()
                .filter(|(_, y)| y.abs() < 0.02)
                .map(|(i, _)| FORCE_NAMES[*i])
                .collect();
            if near.len() > 1 {
                coincide = format!(
                    " At θₛ {} all end near 0; their hollow markers of different shapes overlap without hiding each other.",
                    near.join(" and ")
                );
            }
        }
        figs.push(
            Figure::new(&format!("variant_{}.svg", variant_stem(*variant)), format!("{}: contact forces", variant_name(*variant)), (1300, 540), (1, 2), panels, 170)
                .caption(format!(
                    "Contact forces for {} ({}), against time {} and against θ from rest at the top.{zero_text}{holder}{coincide} {forces_units}",
                    variant_name(*variant),
                    super::data::paper_ref(*variant),
                    start_text()
                )),
        );
    }

    figs.extend(plane_figures(data, cfg));
    figs
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
    p.series.push(stagger(
        Series::new("|F₁|/N₁: at the floor", PALETTE[0], floor.clone()).shape(Shape::Circle),
        n,
        0,
        2,
    ));
    p.series.push(stagger(
        Series::new("|F₂₁|/N₁₂: between the cylinders", PALETTE[1], cont.clone())
            .dashed(Dash::Dashed)
            .shape(Shape::Square),
        n,
        1,
        2,
    ));
    p.lines.push(sep_line(
        ths,
        format!("θₛ = {} (|F₂₁|/N₁₂ → ∞)", fmt(ths, 4)),
    ));
    for mu in MU_VALUES {
        p.lines.push(RefLine {
            at: text_f64(mu),
            vertical: false,
            color: (120, 120, 120),
            dash: Dash::Dotted,
            label: format!("μ = {mu}"),
        });
    }
    let mut contact_onsets = Vec::new();
    let mut floor_onsets = Vec::new();
    for (mu, r) in MU_VALUES.iter().zip(&data.mu) {
        let Ok(s) = r else { continue };
        let m = text_f64(mu);
        if let Some(a) = extra_f(s, "theta_slip_contact") {
            contact_onsets.push(format!("{mu}: {}", fmt(a, 3)));
            p.markers.push(Marker {
                at: (a, m),
                color: PALETTE[1],
                shape: Shape::TriangleDown,
                filled: true,
                title: format!(
                    "μ = {mu}: the contact between the cylinders starts to slip at θ = {}",
                    fmt(a, 4)
                ),
                label: None,
            });
        }
        if let Some(a) = extra_f(s, "theta_slip_floor") {
            floor_onsets.push(format!("{mu}: {}", fmt(a, 3)));
            p.markers.push(Marker {
                at: (a, m),
                color: PALETTE[0],
                shape: Shape::Triangle,
                filled: true,
                title: format!("μ = {mu}: the floor starts to slip at θ = {}", fmt(a, 4)),
                label: None,
            });
        }
    }
    p.legend.push(LegendEntry {
        label: "slip onset between the cylinders, at μ".into(),
        color: PALETTE[1],
        dash: None,
        shape: Some(Shape::TriangleDown),
        filled: true,
    });
    if !floor_onsets.is_empty() {
        p.legend.push(LegendEntry {
            label: "slip onset at the floor, at μ".into(),
            color: PALETTE[0],
            dash: None,
            shape: Some(Shape::Triangle),
            filled: true,
        });
    }
    // the floor's maximum, verified
    let fmax = main_sep.and_then(|s| {
        Some((
            extra_f(s, "mu_floor_max")?,
            extra_f(s, "theta_mu_floor_max")?,
        ))
    });
    if let Some((m, a)) = fmax {
        p.markers.push(Marker {
            at: (a, m),
            color: PALETTE[0],
            shape: Shape::Diamond,
            filled: true,
            title: format!(
                "largest |F₁|/N₁ before separation: {} at θ = {}",
                fmt(m, 4),
                fmt(a, 4)
            ),
            label: Some(format!("max {}", fmt(m, 4))),
        });
    }
    p.legend.push(sep_legend_plain());
    p.yrange = Some((0.0, 1.05));
    p.xrange = Some((0.0, (ths * 10.0).ceil() / 10.0 + 0.05));
    // caption claims from the data
    let f1 = column(&c.rows, 0, AF[0]);
    let (f1_sign, f1_changes) = sign_text(&f1[1..], "θ");
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
    Figure::single("main_friction.svg", "Main case: friction coefficient needed, from rest at the top".into(), (1000, 560), p, 250)
        .caption(format!(
            "The friction coefficients that rolling without slipping needs: |F₁|/N₁ at the floor and |F₂₁|/N₁₂ between the cylinders, \
             main case, from rest at the top. {floor_text}; at θₛ it is {}. F₂₁ stays finite while N₁₂ → 0, so the coefficient needed \
             between the cylinders grows without bound as θ → θₛ: for any finite μ the upper cylinder slips before it separates. \
             Dotted levels: the μ of the table \"Where rolling first fails\"; triangles: where each level is first exceeded \
             (between the cylinders at θ = {}{}). The axis is cut at μ = 1.05.",
            fmt(floor_end, 4),
            contact_onsets.join(", "),
            if floor_onsets.is_empty() {
                String::new()
            } else {
                format!("; at the floor at θ = {}", floor_onsets.join(", "))
            }
        ))
}

fn sep_legend_plain() -> LegendEntry {
    LegendEntry {
        label: "separation θₛ (N₁₂ = 0)".into(),
        color: SEP_COLOR,
        dash: Some(Dash::Dotted),
        shape: None,
        filled: false,
    }
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

fn plane_figures(data: &Data, cfg: &Config) -> Vec<Figure> {
    let pd = cfg.plot_digits;
    let mut figs = Vec::new();
    let plane_text = "Both contacts rolling, from rest at the top; m₁ = r₁ = r₂ = g = 1, k₁ = 1/2 (a solid lower cylinder); \
                      k₂ = I₂/(m₂r₂²) is the upper cylinder's moment of inertia in units of m₂r₂² (0: a point mass on the rim's \
                      axis, 1/2: solid, 1: thin-walled tube, 2: a bobbin).";

    // θs against m2/m1 for several k2, with the fixed-lower limits
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
        let n = pts.len();
        p.series.push(stagger(
            Series::new(format!("k₂ = {k2}"), PALETTE[j], pts)
                .shape(SHAPES[j])
                .direct(format!("k₂ = {k2}")),
            n,
            j,
            PLANE_K2.len(),
        ));
        let lim = fixed_closed_form(text_f64(k2));
        p.series
            .push(Series::new("", PALETTE[j], vec![(xr.0, lim), (xr.1, lim)]).dashed(Dash::Dashed));
    }
    p.legend.push(LegendEntry {
        label: "dashed, same colour: fixed lower cylinder, arccos(2/(3 + k₂))".into(),
        color: PALETTE[6],
        dash: Some(Dash::Dashed),
        shape: None,
        filled: false,
    });
    figs.push(
        Figure::single("plane_ratio.svg", "Separation angle over the mass ratio, for several k₂".into(), (1100, 600), p, 230).caption(format!(
            "θₛ against m₂/m₁ from {} to {} (log scale) for k₂ = {}, each curve labelled at its end. Dashed, in the same colour: the \
             fixed-lower-cylinder value arccos(2/(3 + k₂)) of eq. (36), the limit m₂/m₁ → 0. {plane_text}",
            ratios[0],
            ratios[ratios.len() - 1],
            PLANE_K2.join(", ")
        )),
    );

    // θs against k2 for several m2/m1, with the fixed-lower curve
    let ks = k2_grid(cfg.k2_steps);
    let mut p = Panel::new("", K2_DEF, "θₛ  [rad]");
    p.xrange = Some((0.0, 2.0));
    for (j, r) in PLANE_TABLE_RATIOS.iter().enumerate() {
        let pts: Vec<(f64, f64)> = ks
            .iter()
            .filter_map(|k| Some((text_f64(k), plane_value(data, FloorKey::Roll, r, k, pd)?)))
            .collect();
        let n = pts.len();
        p.series.push(stagger(
            Series::new(format!("m₂/m₁ = {r}"), PALETTE[j], pts)
                .shape(SHAPES[j])
                .direct(format!("m₂/m₁ = {r}")),
            n,
            j,
            PLANE_TABLE_RATIOS.len(),
        ));
    }
    let curve: Vec<(f64, f64)> = (0..=200)
        .map(|i| {
            let k = 2.0 * f64::from(i) / 200.0;
            (k, fixed_closed_form(k))
        })
        .collect();
    p.series.push(
        Series::new(
            "fixed lower cylinder: arccos(2/(3 + k₂))",
            PALETTE[6],
            curve,
        )
        .dashed(Dash::Dashed),
    );
    for k in &ks {
        if let Some(v) = plane_value(data, FloorKey::Fixed, "1", k, pd) {
            p.markers.push(Marker {
                at: (text_f64(k), v),
                color: (255, 255, 255),
                shape: Shape::Circle,
                filled: true,
                title: format!("oracle, fixed lower cylinder, k₂ = {k}: θₛ = {}", fmt(v, 5)),
                label: None,
            });
        }
    }
    p.legend.push(LegendEntry {
        label: "oracle, fixed lower cylinder".into(),
        color: (255, 255, 255),
        dash: None,
        shape: Some(Shape::Circle),
        filled: true,
    });
    let flat = flattest_k2(data, cfg);
    let cross = flat
        .as_ref()
        .map(|f| format!(" The curves come closest together near k₂ ≈ {} (θₛ ≈ {}°): there θₛ hardly depends on m₂/m₁ (see the heat map).", fmt(f.k2, 2), fmt(f.mean, 1)))
        .unwrap_or_default();
    figs.push(
        Figure::single("plane_k2.svg", "Separation angle over k₂, for several mass ratios".into(), (1100, 600), p, 230).caption(format!(
            "θₛ against k₂ for m₂/m₁ = {}, each curve labelled at its end. Black dashed: the closed form arccos(2/(3 + k₂)) for a \
             fixed lower cylinder (eq. 36); the white circles on it are the oracle's values for a fixed lower cylinder.{cross} {plane_text}",
            PLANE_TABLE_RATIOS.join(", ")
        )),
    );

    if let Some(f) = heatmap(data, cfg, flat.as_ref(), plane_text) {
        figs.push(f);
    }
    figs
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

/// θs over (m₂/m₁, k₂): a smooth raster interpolated bilinearly between the
/// oracle's nodes, labelled contours, the colour scale fitted to the data.
fn heatmap(data: &Data, cfg: &Config, flat: Option<&Flat>, plane_text: &str) -> Option<Figure> {
    let (hr, hk, z) = heat_grid(data, cfg);
    let xs: Vec<f64> = hr.iter().map(|r| text_f64(r).log10()).collect();
    let ys: Vec<f64> = hk.iter().map(|k| text_f64(k)).collect();
    let finite: Vec<f64> = z
        .iter()
        .flatten()
        .copied()
        .filter(|v| v.is_finite())
        .collect();
    let zlo = finite.iter().copied().fold(f64::INFINITY, f64::min);
    let zhi = finite.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    if !(zlo.is_finite() && zhi.is_finite() && xs.len() > 1 && ys.len() > 1) {
        return None;
    }
    let lo = zlo;
    let hi = zhi.max(zlo + 1e-9);
    // contour levels every 5° inside the data
    let step = 5.0;
    let levels: Vec<f64> = ((lo / step).ceil() as i64..=(hi / step).floor() as i64)
        .map(|i| i as f64 * step)
        .collect();
    let mut p = Panel::new("", "m₂/m₁  (log scale)", K2_DEF);
    p.xscale = Scale::Log;
    p.xrange = Some((10f64.powf(xs[0]), 10f64.powf(xs[xs.len() - 1])));
    p.yrange = Some((ys[0], ys[ys.len() - 1]));
    // raster: bilinear in (log10 ratio, k2)
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
    p.raster = Some(Raster {
        x: (xs[0], xs[xs.len() - 1]),
        y: (ys[0], ys[ys.len() - 1]),
        w,
        h,
        pixels,
    });
    let mut level_k2 = Vec::new();
    for &level in &levels {
        let lines = chain(&contour(&xs, &ys, &z, level));
        for line in lines {
            let pts: Vec<(f64, f64)> = line.iter().map(|&(x, y)| (10f64.powf(x), y)).collect();
            // k2 range of the contour over m2/m1 from 0.1 to 10 (the curves θs(k2)),
            // and its k2 at the ends of the whole range
            let mid: Vec<f64> = line
                .iter()
                .filter(|q| (-1.0 - 1e-9..=1.0 + 1e-9).contains(&q.0))
                .map(|q| q.1)
                .collect();
            let kmin = mid.iter().copied().fold(f64::INFINITY, f64::min);
            let kmax = mid.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            let xspan = mid.len() as f64;
            let lo_end = line.iter().min_by(|a, b| a.0.total_cmp(&b.0)).copied();
            let hi_end = line.iter().max_by(|a, b| a.0.total_cmp(&b.0)).copied();
            let covers =
                line.iter().any(|q| q.0 <= -1.0 + 1e-9) && line.iter().any(|q| q.0 >= 1.0 - 1e-9);
            if covers {
                level_k2.push((level, kmin, kmax, xspan, lo_end, hi_end));
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
    // the flattest contour that crosses the whole range of mass ratios
    let flattest = level_k2
        .iter()
        .min_by(|a, b| (a.2 - a.1).total_cmp(&(b.2 - b.1)))
        .cloned();
    let contour_text = flattest
        .filter(|f| f.2 - f.1 < 0.05)
        .map(|(l, a, b, _, lo, hi)| {
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
    let flat_text = flat
        .map(|f| {
            format!(
                "{contour_text} Over m₂/m₁ from 0.1 to 10, θₛ varies least on the row k₂ = {} of the grid (by {}°, around {}°): the curves \
                 of θₛ against k₂ for different m₂/m₁ come closest together there (figure above).",
                fmt(f.row, 3),
                fmt(f.spread, 2),
                fmt(f.mean, 1)
            )
        })
        .unwrap_or(contour_text);
    let mut csv = String::from("m2_over_m1,k2,theta_s_deg\n");
    for (j, k) in hk.iter().enumerate() {
        for (i, r) in hr.iter().enumerate() {
            csv.push_str(&format!(
                "{r},{k},{}\n",
                super::plot::csv_num(z[j][i], cfg.plot_digits as usize)
            ));
        }
    }
    let mut fig = Figure::single(
        "plane_heatmap.svg",
        "Separation angle θₛ over the parameter plane".into(),
        (1000, 660),
        p,
        130,
    );
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
