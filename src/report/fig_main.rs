//! The main case (identical solid cylinders, both contacts rolling): its
//! motion through separation and flight, its forces against θ, the
//! friction rolling needs, and the two branches from the branch point θ*.
//!
//! Captions are written from the data they describe.

use super::data::{Data, ThetaCurve, TimeCurve, MU_VALUES, THETA0_TIME};
use super::model::{
    fmt, order, q_force, q_t, q_theta, rad, Band, Dash, Digits, Figure, LegendEntry, Marker, Panel,
    Quantity, RefLine, Series, Shape, PALETTE, REF,
};
use super::track::Track;
use crate::motion::Kind;

/// Force columns of a θ row (θ first).
pub const AF: [usize; 4] = [1, 2, 3, 4];
/// θ̇ in a θ row.
pub const A_THD: usize = 5;
/// μ needed at the floor and between the cylinders in a θ row.
pub const A_MU: [usize; 2] = [7, 8];
/// The forces' names and ASCII names.
pub const FORCES: [(&str, &str); 4] = [("F₁", "F1"), ("N₁", "N1"), ("F₂₁", "F21"), ("N₁₂", "N12")];
/// One line style per force (with colour and marker shape).
pub const FORCE_DASH: [Dash; 4] = [Dash::Solid, Dash::Dashed, Dash::DashDot, Dash::Dotted];

/// Shading of the window where parting is lawful, of flight, and of
/// sliding at each contact.
pub const WINDOW: (u8, u8, u8) = (232, 232, 232);
/// Flight.
pub const FLIGHT: (u8, u8, u8) = (214, 232, 248);

/// Units of every figure of identical cylinders.
pub const UNITS: &str = "Identical solid cylinders, m₁ = m₂ = r₁ = r₂ = g = 1, k₁ = k₂ = 1/2; time in τ = √(r₁/g), forces in m₁g, angles in radians (degrees in parentheses).";

/// Periodic markers, staggered by curve.
pub fn stagger(s: Series, index: usize, of: usize) -> Series {
    let n = s.points.len();
    let every = (n / 7).max(2);
    let offset = (every * (index + 1)) / (of + 1);
    s.every(every, offset)
}

/// The vertical line of the branch point (θ* or t*).
pub fn star_line(at: f64, label: String, d: Digits) -> RefLine {
    RefLine::vertical(at, Dash::Dashed, label.clone())
        .verified(
            d,
            format!("branch point: {label}; from here the cylinders may stay together or part"),
        )
        .key("branch_point")
}

/// The vertical line of separation (θs or tₛ).
pub fn sep_line(at: f64, label: String, d: Digits) -> RefLine {
    RefLine::vertical(at, Dash::Dotted, label.clone())
        .verified(d, format!("separation: {label}"))
        .key("separation")
}

/// The legend entries of the branch point and of separation.
pub fn event_legend(star: bool) -> Vec<LegendEntry> {
    let mut v = Vec::new();
    if star {
        v.push(LegendEntry::line(
            "θ*: branch point (parting lawful from here)",
            REF,
            Dash::Dashed,
            order::BRANCH,
        ));
    }
    v.push(LegendEntry::line(
        "separation (N₁₂ = 0)",
        REF,
        Dash::Dotted,
        order::SEPARATION,
    ));
    v
}

fn pd(data: &Data) -> Digits {
    Digits::Verified(data.plot_digits)
}

/// θ, dθ/dt, φ₁, φ₂ of the main case against t, through separation and
/// the flight to the first impact.
pub fn main_motion(data: &Data) -> Option<Figure> {
    let c: &TimeCurve = data.time.first()?.as_ref().ok()?;
    let tr = &c.track;
    let d = pd(data);
    let t_star = tr.event(Kind::Indeterminate).map(|e| e.t);
    let sep = tr.event(Kind::Separation)?;
    let imp = tr.event(Kind::Impact);
    let cols = [
        ("theta", "θ", Quantity::new("theta", "rad", "θ (rad)")),
        (
            "theta_dot",
            "dθ/dt",
            Quantity::new("theta_dot", "rad/tau", "dθ/dt (rad/τ)"),
        ),
        ("phi1", "φ₁", Quantity::new("phi1", "rad", "φ₁ (rad)")),
        ("phi2", "φ₂", Quantity::new("phi2", "rad", "φ₂ (rad)")),
    ];
    let mut panels = Vec::new();
    for (k, (col, name, q)) in cols.iter().enumerate() {
        let (pts, ph) = tr.col(col);
        let mut p = Panel::new("", q_t(), q.clone());
        p.series.push(
            Series::new("", PALETTE[0], pts)
                .csv(format!("curve={col}"), None)
                .phases(ph)
                .digits(Digits::Exact, d),
        );
        if let Some(ts) = t_star {
            let l = if k == 0 {
                format!("t* = {}", fmt(ts, 3))
            } else {
                String::new()
            };
            p.lines.push(star_line(ts, l, d));
            p.bands.push(Band {
                x: (ts, sep.t),
                color: WINDOW,
                title: "window where parting is lawful (θ* to θs)".into(),
            });
        }
        let l = if k == 0 {
            format!("tₛ = {}", fmt(sep.t, 3))
        } else {
            String::new()
        };
        p.lines.push(sep_line(sep.t, l, d));
        if let Some(i) = imp {
            p.bands.push(Band {
                x: (sep.t, i.t),
                color: FLIGHT,
                title: format!(
                    "flight: cylinder 2 free, to the first impact at t = {}",
                    fmt(i.t, 4)
                ),
            });
        }
        let _ = name;
        panels.push(p);
    }
    let mut f = Figure::new(
        "main_motion",
        format!("Main case: the motion from θ₀ = {THETA0_TIME} to the first impact"),
        panels,
        2,
    )
    .heights(150.0, 150.0);
    f.share_x = true;
    f.legend = event_legend(t_star.is_some());
    f.legend.push(LegendEntry::swatch(
        "window where parting is lawful",
        WINDOW,
    ));
    f.legend
        .push(LegendEntry::swatch("flight to the first impact", FLIGHT));
    let star = tr.value("theta_indeterminate").map_or(String::new(), |s| {
        format!(" At the branch point θ* = {} (t* = {}) the rigid-body motion stops being unique: the cylinders may part anywhere up to θₛ; this motion follows the default branch and stays together (see the branch figure).", rad(s, 4), fmt(t_star.unwrap_or(f64::NAN), 4))
    });
    let impact = imp.map_or(String::new(), |i| {
        format!(" After separation cylinder 2 flies freely (shaded blue) until the first impact at t = {}, where the model ends.", fmt(i.t, 4))
    });
    Some(f.caption(format!(
        "θ, dθ/dt, φ₁ and φ₂ against time for the paper's main case from rest at θ₀ = {THETA0_TIME}. Separation (N₁₂ = 0) at tₛ = {}, θₛ = {}.{star}{impact} Every event time is a sample point and the lines break at every phase boundary. {UNITS}",
        fmt(sep.t, 4),
        rad(sep.theta, 4),
    )))
}

/// The four forces of one θ curve as series (forces that vanish left out).
pub fn theta_force_series(c: &ThetaCurve, zero: &[bool; 4], d: Digits) -> Vec<Series> {
    let live: Vec<usize> = (0..4).filter(|&i| !zero[i]).collect();
    live.iter()
        .enumerate()
        .map(|(k, &i)| {
            let pts: Vec<(f64, f64)> = c.rows.iter().map(|r| (r[0], r[AF[i]])).collect();
            let end = pts.last().map_or(String::new(), |q| {
                format!("{} at θₛ: {}", FORCES[i].0, fmt(q.1, 4))
            });
            stagger(
                Series::new(FORCES[i].0, PALETTE[i], pts)
                    .csv(
                        format!("force={}", FORCES[i].1),
                        Some(Quantity::new(FORCES[i].1, "m1*g", "")),
                    )
                    .dashed(FORCE_DASH[i])
                    .shape(super::model::SHAPES[i])
                    .end_marker(end)
                    .digits(Digits::Exact, d),
                k,
                live.len(),
            )
        })
        .collect()
}

/// The forces of the main case against θ, from rest at the top.
pub fn main_forces(data: &Data) -> Option<Figure> {
    let c = data.theta.first()?.as_ref().ok()?;
    let d = pd(data);
    let ths = c.sep.theta_s.value.to_f64();
    let mut p = Panel::new("", q_theta(), q_force());
    p.series = theta_force_series(c, &[false; 4], d);
    if let Some(s) = c.star {
        p.lines.push(star_line(s, format!("θ* = {}", fmt(s, 4)), d));
    }
    p.lines
        .push(sep_line(ths, format!("θₛ = {}", fmt(ths, 4)), d));
    let top = |i: usize| c.rows.first().map_or(f64::NAN, |r| r[AF[i]]);
    let mut f = Figure::new(
        "main_forces",
        "Main case: the contact forces against θ, from rest at the top",
        vec![p],
        1,
    )
    .heights(190.0, 170.0);
    f.legend = event_legend(c.star.is_some());
    f.legend.push(LegendEntry::marker(
        "value at separation",
        REF,
        Shape::Circle,
        false,
        order::SEPARATION + 1,
    ));
    let star = c.star.map_or(String::new(), |s| {
        format!(" From θ* = {} the free relative normal acceleration is positive while N₁₂ > 0: the cylinders may part there (velocity-level contact solvers do) or stay together to θₛ (the branch followed).", rad(s, 4))
    });
    // the sign of F₁ past the top, as the data has it
    let f1: Vec<f64> = c.rows.iter().skip(1).map(|r| r[AF[0]]).collect();
    let f1_text = if f1.iter().all(|v| *v > 0.0) {
        " F₁ keeps its sign (positive, along +x) all the way to separation."
    } else if f1.iter().all(|v| *v < 0.0) {
        " F₁ keeps its sign (negative) all the way to separation."
    } else {
        " F₁ changes sign before separation."
    };
    Some(f.caption(format!(
        "F₁, N₁ (the floor's force on cylinder 1), F₂₁ and N₁₂ (cylinder 1's force on cylinder 2, tangential and normal) against θ, from rest at the top (the limit θ₀ → 0+). At the top N₁ = {} (the weight of both) and N₁₂ = {}. Separation at θₛ = {} = π/3, where N₁₂ = 0 while F₂₁ = {}.{f1_text}{star} {UNITS}",
        fmt(top(1), 3),
        fmt(top(3), 3),
        rad(ths, 5),
        fmt(c.rows.last().map_or(f64::NAN, |r| r[AF[2]]), 4),
    )))
}

/// The friction rolling needs at each contact, with the slip onsets of the
/// table's μ (which contact slips: the marker's shape and colour).
pub fn main_friction(data: &Data) -> Option<Figure> {
    let c = data.theta.first()?.as_ref().ok()?;
    let d = pd(data);
    let ths = c.sep.theta_s.value.to_f64();
    let q = Quantity::new("mu_needed", "1", "friction needed, |F|/N");
    let mut p = Panel::new("", q_theta(), q);
    let floor: Vec<(f64, f64)> = c.rows.iter().map(|r| (r[0], r[A_MU[0]])).collect();
    let cont: Vec<(f64, f64)> = c.rows.iter().map(|r| (r[0], r[A_MU[1]])).collect();
    p.series = vec![
        stagger(
            Series::new("at the floor, |F₁|/N₁", PALETTE[0], floor.clone())
                .csv("contact=floor", Some(Quantity::new("mu_floor", "1", "")))
                .shape(Shape::Circle)
                .digits(Digits::Exact, d),
            0,
            2,
        ),
        stagger(
            Series::new("between the cylinders, |F₂₁|/N₁₂", PALETTE[1], cont)
                .csv(
                    "contact=cylinders",
                    Some(Quantity::new("mu_contact", "1", "")),
                )
                .dashed(Dash::Dashed)
                .shape(Shape::Square)
                .digits(Digits::Exact, d),
            1,
            2,
        ),
    ];
    // the need between the cylinders grows without bound: the axis is cut
    p.yrange = Some((-0.04, 1.08));
    for mu in MU_VALUES {
        let v = super::data::text_f64(mu);
        p.lines.push(
            RefLine::horizontal(v, (150, 150, 150), Dash::Dotted, format!("μ = {mu}"))
                .verified(Digits::Exact, format!("μ = {mu}"))
                .key(format!("mu={mu}")),
        );
    }
    if let Some(s) = c.star {
        p.lines.push(star_line(s, format!("θ* = {}", fmt(s, 3)), d));
    }
    p.lines
        .push(sep_line(ths, format!("θₛ = {}", fmt(ths, 3)), d));
    let (mut at_c, mut at_f) = (Vec::new(), Vec::new());
    for (mu, r) in MU_VALUES.iter().zip(&data.mu) {
        let Ok(s) = r else { continue };
        for (name, shape, color, what, list) in [
            (
                "theta_slip_contact",
                Shape::TriangleDown,
                PALETTE[1],
                "the contact between the cylinders",
                &mut at_c,
            ),
            (
                "theta_slip_floor",
                Shape::Triangle,
                PALETTE[0],
                "the floor",
                &mut at_f,
            ),
        ] {
            if let Some(a) = s.extra.iter().find(|v| v.name == name) {
                let a = a.value.to_f64();
                list.push(format!("μ = {mu}: {}", fmt(a, 3)));
                p.markers.push(
                    Marker::new(
                        shape,
                        (a, super::data::text_f64(mu)),
                        color,
                        format!("μ = {mu}: {what} starts to slip at θ = {}", fmt(a, 4)),
                    )
                    .key(format!(
                        "slip_onset;contact={};mu={mu}",
                        if name.ends_with("floor") {
                            "floor"
                        } else {
                            "cylinders"
                        }
                    ))
                    .digits(Digits::Verified(data.table_digits)),
                );
            }
        }
    }
    let fmax = data
        .sep
        .first()
        .and_then(|r| r.first())
        .and_then(|r| r.as_ref().ok())
        .and_then(|s| {
            let g = |n: &str| {
                s.extra
                    .iter()
                    .find(|v| v.name == n)
                    .map(|v| v.value.to_f64())
            };
            Some((g("mu_floor_max")?, g("theta_mu_floor_max")?))
        });
    if let Some((m, a)) = fmax {
        p.markers.push(
            Marker::new(
                Shape::Diamond,
                (a, m),
                PALETTE[0],
                format!(
                    "largest |F₁|/N₁ before separation: {} at θ = {}",
                    fmt(m, 4),
                    fmt(a, 4)
                ),
            )
            .key("max_mu_floor")
            .digits(Digits::Verified(data.table_digits)),
        );
    }
    let mut f = Figure::new(
        "main_friction",
        "Main case: the friction coefficient rolling needs, from rest at the top",
        vec![p],
        1,
    )
    .heights(190.0, 175.0);
    f.legend = vec![
        LegendEntry::marker(
            "the cylinders start to slip, at μ",
            PALETTE[1],
            Shape::TriangleDown,
            true,
            order::MARK,
        ),
        LegendEntry::marker(
            "the floor starts to slip, at μ",
            PALETTE[0],
            Shape::Triangle,
            true,
            order::MARK + 1,
        ),
        LegendEntry::marker(
            "largest |F₁|/N₁",
            PALETTE[0],
            Shape::Diamond,
            true,
            order::MARK + 2,
        ),
        LegendEntry::line(
            "a friction coefficient μ",
            (150, 150, 150),
            Dash::Dotted,
            order::LIMIT,
        ),
    ];
    f.legend.extend(event_legend(c.star.is_some()));
    let floor_text = fmax.map_or(String::new(), |(m, a)| {
        format!("The floor needs at most |F₁|/N₁ = {} (at θ = {}, diamond), so any μ above it keeps the floor rolling to separation. ", fmt(m, 4), fmt(a, 4))
    });
    let floor_onsets = if at_f.is_empty() {
        "The floor never slips first for these μ.".to_string()
    } else {
        format!(
            "The floor slips first (upward triangles) for {}.",
            at_f.join("; ")
        )
    };
    Some(f.caption(format!(
        "The friction coefficients that rolling without slipping needs: |F₁|/N₁ at the floor and |F₂₁|/N₁₂ between the cylinders, main case, from rest at the top. {floor_text}Between the cylinders the need grows without bound as θ → θₛ, since N₁₂ → 0 while F₂₁ does not: for any finite μ the upper cylinder slips before it separates. Dotted levels: the μ of the table \"Where rolling first fails\"; the cylinders start to slip (downward triangles) at {}. {floor_onsets} The axis is cut at 1.08. {UNITS}",
        at_c.join("; ")
    )))
}

/// The branch figure: N₁₂ and the free relative normal acceleration along
/// the closed branch, the window [θ*, θs], and θ(t) on both branches.
pub fn main_branch(b: &super::branch::BranchData, digits: u32) -> Option<Figure> {
    let d = Digits::Verified(digits);
    let star = b.star;
    let ths = b.theta_s;
    let qa = Quantity::new("value", "m1*g or g", "N₁₂ (m₁g), a (g)");
    let mut pa = Panel::new("(a) along the closed branch", q_theta(), qa);
    let n12: Vec<(f64, f64)> = b.closed.iter().map(|r| (r.0, r.1)).collect();
    let acc: Vec<(f64, f64)> = b.closed.iter().map(|r| (r.0, r.2)).collect();
    pa.series = vec![
        Series::new("N₁₂ on the closed branch", PALETTE[2], n12)
            .csv("N12_closed", Some(Quantity::new("N12", "m1*g", "")))
            .shape(Shape::Circle)
            .every(6, 2)
            .digits(Digits::Exact, d),
        Series::new(
            "a = r θ̇² − g cos θ, free relative normal acceleration",
            PALETTE[1],
            acc,
        )
        .csv("a_free", Some(Quantity::new("a_free", "g", "")))
        .dashed(Dash::Dashed)
        .shape(Shape::Square)
        .every(6, 5)
        .digits(Digits::Exact, d),
    ];
    pa.lines
        .push(RefLine::horizontal(0.0, (150, 150, 150), Dash::Solid, ""));
    pa.lines
        .push(star_line(star, format!("θ* = {}", fmt(star, 4)), d));
    pa.lines
        .push(sep_line(ths, format!("θₛ = {}", fmt(ths, 4)), d));
    pa.bands.push(Band {
        x: (star, ths),
        color: WINDOW,
        title: "parting is lawful from θ* to θs".into(),
    });
    pa.markers.push(
        Marker::new(
            Shape::Diamond,
            (star, 0.0),
            PALETTE[6],
            format!("θ* = {}: a turns positive while N₁₂ > 0", fmt(star, 6)),
        )
        .key("theta_star")
        .digits(d),
    );
    let t_star = b.stay.event(Kind::Indeterminate).map(|e| e.t);
    let t_sep = b.stay.event(Kind::Separation).map(|e| e.t);
    let t_end = [&b.stay, &b.part]
        .iter()
        .filter_map(|tr| tr.event(Kind::Impact).map(|e| e.t))
        .fold(f64::NAN, f64::max);
    let t_from = t_star.map_or(0.0, |t| (t - 0.8).max(0.0));
    let zoom = t_end
        .is_finite()
        .then_some((t_from, t_end + 0.04 * (t_end - t_from)));
    let mut pb = Panel::new(
        "(b) N₁₂ on both branches",
        q_t(),
        Quantity::new("N12", "m1*g", "N₁₂ (m₁g)"),
    );
    let mut pc = Panel::new(
        "(c) the gap between the cylinders",
        q_t(),
        Quantity::new("gap", "r1", "gap (r₁)"),
    );
    for (name, tr, color, dash, key) in [
        (
            "stay: together to θₛ (default)",
            &b.stay,
            PALETTE[0],
            Dash::Solid,
            "branch=stay",
        ),
        (
            "part: apart at θ*",
            &b.part,
            PALETTE[3],
            Dash::Dashed,
            "branch=part",
        ),
    ] {
        let (n12, ph) = tr.col("N12");
        pb.series.push(
            Series::new(name, color, n12)
                .csv(key, None)
                .phases(ph)
                .dashed(dash)
                .digits(Digits::Exact, d),
        );
        let (gap, ph) = b.gap(tr);
        let last_gap = gap
            .iter()
            .rev()
            .find(|q| q.1.is_finite())
            .map_or(f64::NAN, |q| q.1);
        pc.series.push(
            Series::new(name, color, gap)
                .csv(key, None)
                .phases(ph)
                .dashed(dash)
                .digits(Digits::Exact, d),
        );
        if let Some(e) = tr.event(Kind::Separation) {
            pb.markers.push(
                Marker::new(
                    Shape::Circle,
                    (e.t, 0.0),
                    color,
                    format!(
                        "{key}: the cylinders part at t = {}, θ = {}",
                        fmt(e.t, 4),
                        fmt(e.theta, 4)
                    ),
                )
                .key(format!("{key};separation"))
                .hollow()
                .digits(d),
            );
        }
        if let Some(e) = tr.event(Kind::Impact) {
            pc.markers.push(
                Marker::new(
                    Shape::Cross,
                    (e.t, last_gap),
                    color,
                    format!(
                        "{key}: first impact at t = {}, the gap then {}",
                        fmt(e.t, 4),
                        fmt(last_gap, 4)
                    ),
                )
                .key(format!("{key};impact"))
                .digits(d),
            );
        }
    }
    for (k, p) in [&mut pb, &mut pc].into_iter().enumerate() {
        p.xrange = zoom;
        if let Some(t) = t_star {
            let l = if k == 0 {
                format!("t* = {}", fmt(t, 3))
            } else {
                String::new()
            };
            p.lines.push(star_line(t, l, d));
        }
        if let Some(t) = t_sep {
            let l = if k == 0 {
                format!("tₛ = {}", fmt(t, 3))
            } else {
                String::new()
            };
            p.lines.push(sep_line(t, l, d));
        }
        if let (Some(a), Some(b)) = (t_star, t_sep) {
            p.bands.push(Band {
                x: (a, b),
                color: WINDOW,
                title: "parting is lawful from t* to tₛ".into(),
            });
        }
    }
    let mut f = Figure::new(
        "main_branch",
        format!("Main case from θ₀ = {THETA0_TIME}: where the motion is not unique, and its two branches"),
        vec![pa, pb, pc],
        3,
    )
    .heights(175.0, 150.0);
    f.legend = vec![
        LegendEntry::marker(
            "θ*: a = 0 while N₁₂ > 0",
            PALETTE[6],
            Shape::Diamond,
            true,
            order::MARK,
        ),
        LegendEntry::marker(
            "the cylinders part",
            REF,
            Shape::Circle,
            false,
            order::SEPARATION + 1,
        ),
        LegendEntry::marker("first impact", REF, Shape::Cross, false, order::IMPACT),
        LegendEntry::swatch("[θ*, θₛ]: parting lawful", WINDOW),
    ];
    f.legend.extend(event_legend(true));
    let part_sep = b.part.event(Kind::Separation);
    let impacts: Vec<String> = [("stay", &b.stay), ("part", &b.part)]
        .iter()
        .filter_map(|(n, tr)| {
            tr.event(Kind::Impact)
                .map(|e| format!("{n} at t = {}", fmt(e.t, 4)))
        })
        .collect();
    Some(f.caption(format!(
        "(a) Along the closed branch (the cylinders kept together) of the main case from rest at θ₀ = {THETA0_TIME}: the normal force N₁₂ and the relative normal acceleration a = r θ̇² − g cos θ (r = r₁ + r₂) that the cylinders would have if the contact force vanished (cylinder 1 then rolls freely, ẍ₁ = 0). a turns positive at the branch point θ* = {} while N₁₂ > 0: from there the rigid-body model allows both staying together (N₁₂ > 0, a = 0) and parting (N₁₂ = 0, a > 0), anywhere in the window [θ*, θₛ] = [{}, {}] (shaded). (b) N₁₂ and (c) the gap between the surfaces against t on the two branches, from t* − 0.8 to the first impact: `stay` (the default, the limit of stiff compliant contact) keeps the cylinders together until N₁₂ reaches 0 at tₛ = {}; `part` (`cylroll separation --branch part`, what velocity-level contact solvers do) parts at t* = {}, θ = {}, where N₁₂ drops from {} to 0, and its gap opens earlier. Each continues in flight to its first impact (crosses: {}). {UNITS}",
        rad(star, 6),
        fmt(star, 4),
        fmt(ths, 4),
        t_sep.map_or("–".into(), |t| fmt(t, 4)),
        part_sep.map_or("–".into(), |e| fmt(e.t, 4)),
        part_sep.map_or("–".into(), |e| fmt(e.theta, 6)),
        fmt(
            b.closed
                .iter()
                .find(|r| (r.0 - star).abs() < 1e-9)
                .map_or(f64::NAN, |r| r.1),
            4
        ),
        impacts.join(", "),
    )))
}

/// θ* of a track (the answer's verified `theta_indeterminate`).
pub fn track_star(t: &Track) -> Option<f64> {
    t.value("theta_indeterminate")
}
