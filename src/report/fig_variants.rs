//! The six contact models side by side: their motion against time (one
//! figure, the models overlaid) and their forces against θ (one faceted
//! figure, the same axes in every facet).

use super::data::{paper_ref, variant_name, Data, THETA0_TIME, VARIANTS};
use super::fig_main::{
    event_legend, sep_line, stagger, star_line, theta_force_series, FORCES, UNITS,
};
use super::model::{
    fmt, order, q_force, q_t, q_theta, Dash, Digits, Figure, LegendEntry, Panel, Quantity, Series,
    Shape, PALETTE, REF, SHAPES,
};
use crate::model::{Contact, Floor};

/// Short name of a model: floor/contact.
pub fn short(v: usize) -> String {
    format!("{}/{}", VARIANTS[v].0, VARIANTS[v].1)
}

/// Line style by floor: rolling solid, frictionless dashed, held dash-dot.
fn dash(v: usize) -> Dash {
    match VARIANTS[v].0 {
        Floor::Roll => Dash::Solid,
        Floor::Slip => Dash::Dashed,
        Floor::Fixed => Dash::DashDot,
    }
}

/// Whether force `i` (F1, N1, F21, N12) vanishes in model `v`.
pub fn force_is_zero(v: usize, i: usize) -> bool {
    let (floor, contact) = VARIANTS[v];
    (i == 0 && floor == Floor::Slip) || (i == 2 && contact == Contact::Slip)
}

/// θ, dθ/dt, φ₁, φ₂ of every model against t, to its separation.
pub fn variants_motion(data: &Data) -> Option<Figure> {
    let d = Digits::Verified(data.plot_digits);
    let cols = [
        ("theta", Quantity::new("theta", "rad", "θ (rad)")),
        (
            "theta_dot",
            Quantity::new("theta_dot", "rad/tau", "dθ/dt (rad/τ)"),
        ),
        ("phi1", Quantity::new("phi1", "rad", "φ₁ (rad)")),
        ("phi2", Quantity::new("phi2", "rad", "φ₂ (rad)")),
    ];
    let curves: Vec<(usize, &super::track::Track)> = data
        .time
        .iter()
        .enumerate()
        .filter_map(|(v, r)| r.as_ref().ok().map(|c| (v, &c.track)))
        .collect();
    if curves.is_empty() {
        return None;
    }
    let mut panels = Vec::new();
    let mut zero = Vec::new();
    for (col, q) in &cols {
        let mut p = Panel::new("", q_t(), q.clone());
        for (k, &(v, tr)) in curves.iter().enumerate() {
            let sep = tr.event(crate::motion::Kind::Separation);
            // up to separation only
            let (mut pts, mut ph) = tr.col(col);
            if let Some(e) = sep {
                let keep = pts.iter().position(|q| q.0 > e.t).unwrap_or(pts.len());
                pts.truncate(keep);
                ph.truncate(keep);
            }
            if pts.iter().all(|q| !q.1.is_finite() || q.1.abs() < 1e-12) {
                zero.push(format!(
                    "{} ≡ 0 for {}",
                    q.label.split(' ').next().unwrap_or(""),
                    short(v)
                ));
                continue;
            }
            let end = sep.map_or(String::new(), |e| {
                format!(
                    "{}: separation at t = {}, θₛ = {}",
                    variant_name(VARIANTS[v]),
                    fmt(e.t, 4),
                    fmt(e.theta, 4)
                )
            });
            let n = curves.len();
            p.series.push(stagger(
                Series::new(
                    format!("{} ({})", variant_name(VARIANTS[v]), short(v)),
                    PALETTE[v],
                    pts,
                )
                .csv(format!("model={}", short(v)), None)
                .phases(ph)
                .dashed(dash(v))
                .shape(SHAPES[v])
                .end_marker(end)
                .digits(Digits::Exact, d),
                k,
                n,
            ));
        }
        panels.push(p);
    }
    let mut f = Figure::new(
        "variants_motion",
        format!("All contact models: the motion from θ₀ = {THETA0_TIME} to separation"),
        panels,
        2,
    )
    .heights(160.0, 165.0);
    f.share_x = true;
    f.legend.push(LegendEntry::marker(
        "separation (N₁₂ = 0): each curve ends there",
        REF,
        Shape::Circle,
        false,
        order::SEPARATION,
    ));
    let ts: Vec<String> = curves
        .iter()
        .filter_map(|&(v, tr)| {
            tr.event(crate::motion::Kind::Separation)
                .map(|e| format!("{} {}", short(v), fmt(e.t, 3)))
        })
        .collect();
    let zero_text = if zero.is_empty() {
        String::new()
    } else {
        format!(" Not drawn (identically zero): {}.", zero.join("; "))
    };
    Some(f.caption(format!(
        "θ, dθ/dt, φ₁ and φ₂ against time for the six contact models (floor rolling, frictionless or holding cylinder 1, times the contact rolling or frictionless), from rest at θ₀ = {THETA0_TIME}, each to its separation (hollow marker): tₛ = {}. Colour, line style (solid: rolling floor, dashed: frictionless floor, dash-dot: held lower cylinder) and marker shape tell the models apart (the legend names them floor/contact).{zero_text} {UNITS}",
        ts.join(", ")
    )))
}

/// The forces against θ from rest at the top, one facet per model, the
/// same axes in every facet.
pub fn variants_forces(data: &Data) -> Option<Figure> {
    let d = Digits::Verified(data.plot_digits);
    let mut panels = Vec::new();
    let mut any_star = false;
    let mut omitted = Vec::new();
    for (v, r) in data.theta.iter().enumerate() {
        let title = format!("{} ({})", short(v), paper_ref(VARIANTS[v]));
        let mut p = Panel::new(title, q_theta(), q_force());
        let Ok(c) = r else {
            p.notes.push("not computed".into());
            panels.push(p);
            continue;
        };
        let zero = [0, 1, 2, 3].map(|i| force_is_zero(v, i));
        p.series = theta_force_series(c, &zero, d);
        for s in &mut p.series {
            s.key = format!("model={};{}", short(v), s.key);
        }
        let names: Vec<&str> = (0..4).filter(|&i| zero[i]).map(|i| FORCES[i].0).collect();
        if !names.is_empty() {
            p.notes.push(format!("{} ≡ 0", names.join(", ")));
            omitted.push(format!("{} for {}", names.join(" and "), short(v)));
        }
        let ths = c.sep.theta_s.value.to_f64();
        if let Some(s) = c.star {
            any_star = true;
            p.lines.push(star_line(s, String::new(), d));
        }
        p.lines
            .push(sep_line(ths, format!("θₛ = {}", fmt(ths, 3)), d));
        panels.push(p);
    }
    if panels.is_empty() {
        return None;
    }
    let mut f = Figure::new(
        "variants_forces",
        "All contact models: the contact forces against θ, from rest at the top",
        panels,
        3,
    )
    .heights(150.0, 150.0);
    f.share_x = true;
    f.share_y = true;
    f.legend = event_legend(any_star);
    f.legend.push(LegendEntry::marker(
        "value at separation",
        REF,
        Shape::Circle,
        false,
        order::SEPARATION + 1,
    ));
    Some(f.caption(format!(
        "F₁, N₁, F₂₁ and N₁₂ against θ for each contact model (floor/contact: roll = rolling, slip = frictionless, fixed = cylinder 1 held), from rest at the top (θ₀ → 0+), on the same axes in every facet. A force at a frictionless contact is zero and not drawn ({}). With the lower cylinder held, F₁ and N₁ are the holder's forces. θ* (dashed) marks the branch point where it applies (not with a held lower cylinder). {UNITS}",
        omitted.join("; ")
    )))
}
