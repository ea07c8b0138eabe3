//! The report's section on finite Coulomb friction: the main case's motion
//! through its phases, its events at three coefficients, and maps of the
//! slip-onset and separation angles over the coefficients, meeting the ideal
//! models at both ends.

use super::data::{log_grid, text_f64};
use super::fig_main::{sep_line, UNITS};
use super::legend::viridis;
use super::model::{
    fmt, order, q_force, q_t, q_theta, rad, Band, ColorBar, Dash, Digits, Figure, LegendEntry,
    Marker, Panel, Patch, Quantity, RefLine, Series, Shape, PALETTE, REF,
};
use super::page::Table;
use super::track::{track, Track};
use super::Config;
use crate::error::Result;
use crate::exact::Exact;
use crate::model::{Contact, Floor, Ideal, Law, Model, Params, Start};
use crate::motion::Kind;
use crate::oracle::{self, Answer as SeparationAnswer, Options, Oracle};

/// θ0 of the friction section (the main case's start).
const THETA0: &str = "1/10";

/// A point of the map over μ: (μ, the first slip onset (θ, contact), θs,
/// the contact opened at an event with N₁₂ > 0).
pub type MapPoint = (f64, Option<(f64, String)>, f64, bool);

/// What the section computes.
pub struct FrictionData {
    /// (μ text, the separation answer) for the event table.
    pub cases: Vec<(String, Result<SeparationAnswer>)>,
    /// The main case at μ = 0.3, sampled at its events.
    pub traj: Result<Track>,
    /// (μ, the first slip onset (θ, contact), θs, the contact opened at the
    /// cone) at equal coefficients on both contacts.
    pub map: Vec<MapPoint>,
    /// Points of the map that had no unique continuation (μ, reason).
    pub map_failed: Vec<(f64, String)>,
    /// θs over (μ_floor, μ_contact): grid values and rows of θs (None: failed).
    pub plane: (Vec<f64>, Vec<Vec<Option<f64>>>),
    /// θs of the ideal models from θ0: roll/roll, slip/slip, roll/slip.
    pub ideal: [f64; 3],
}

fn main_model() -> Model {
    Model::paper_default(Exact::parse("theta0", THETA0, false).expect("theta0"))
}

/// The main model with coefficients μ at the floor and between the cylinders.
fn both(mu_floor: &str, mu_contact: &str) -> Result<Model> {
    main_model().with_laws(
        Law::parse_mu("mu_floor", mu_floor)?,
        Law::parse_mu("mu_contact", mu_contact)?,
    )
}

fn separation(m: &Model, digits: u32) -> Result<SeparationAnswer> {
    oracle::separation(m, &Options::digits(digits))
}

fn value(a: &SeparationAnswer, name: &str) -> f64 {
    a.values
        .iter()
        .find(|v| v.name == name)
        .map_or(f64::NAN, |v| v.value.to_f64())
}

fn ideal_theta_s(floor: Floor, contact: Contact, digits: u32) -> f64 {
    let m = Ideal::new(
        Params::identical_solid(),
        floor,
        contact,
        Start::rest(Exact::parse("theta0", THETA0, false).expect("theta0")),
    )
    .expect("ideal model");
    Oracle::new(&m, digits)
        .and_then(|mut o| o.separation())
        .map_or(f64::NAN, |s| s.theta_s.value.to_f64())
}

/// Computes the section's data.
pub fn compute(cfg: &Config) -> FrictionData {
    let cases: Vec<(String, Result<SeparationAnswer>)> = ["0.3", "1", "10"]
        .iter()
        .map(|mu| {
            (
                mu.to_string(),
                both(mu, mu).and_then(|m| separation(&m, cfg.digits)),
            )
        })
        .collect();
    let traj = both("0.3", "0.3")
        .and_then(|m| track(&m, &Options::digits(cfg.plot_digits), cfg.time_points, None));
    let mut map = Vec::new();
    let mut map_failed = Vec::new();
    for mu in log_grid(-2, 2, cfg.friction_per_decade) {
        let x = text_f64(&mu);
        match both(&mu, &mu).and_then(|m| separation(&m, cfg.plot_digits)) {
            Ok(a) => {
                let onset = a
                    .events
                    .iter()
                    .find(|e| e.kind == Kind::SlipOnset)
                    .map(|e| {
                        let w = e.which.map_or("", |w| w.name());
                        (e.theta.value.to_f64(), w.to_string())
                    });
                let opened = a.notes.iter().any(|n| n.contains("opens while N12"));
                map.push((x, onset, value(&a, "theta_s"), opened));
            }
            Err(e) => map_failed.push((x, e.to_string())),
        }
    }
    let grid = log_grid(-2, 2, cfg.friction_plane_per_decade);
    let gx: Vec<f64> = grid.iter().map(|g| text_f64(g)).collect();
    let plane_rows: Vec<Vec<Option<f64>>> = grid
        .iter()
        .map(|mc| {
            grid.iter()
                .map(|mf| {
                    both(mf, mc)
                        .and_then(|m| separation(&m, cfg.plot_digits))
                        .ok()
                        .map(|a| value(&a, "theta_s"))
                })
                .collect()
        })
        .collect();
    FrictionData {
        cases,
        traj,
        map,
        map_failed,
        plane: (gx, plane_rows),
        ideal: [
            ideal_theta_s(Floor::Roll, Contact::Roll, cfg.plot_digits),
            ideal_theta_s(Floor::Slip, Contact::Slip, cfg.plot_digits),
            ideal_theta_s(Floor::Roll, Contact::Slip, cfg.plot_digits),
        ],
    }
}

/// The event table of the main case at μ = 0.3, 1, 10.
pub fn table(d: &FrictionData) -> Table {
    let mut rows = Vec::new();
    for (mu, a) in &d.cases {
        match a {
            Ok(a) => {
                for e in &a.events {
                    rows.push(vec![
                        format!("={mu}"),
                        e.kind.name().replace('_', " "),
                        e.which.map_or("–", |w| w.name()).to_string(),
                        format!("={}", e.t.text),
                        format!("={}", e.theta.text),
                        e.phase
                            .map_or_else(|| "end of the model".into(), |p| p.to_string()),
                    ]);
                }
            }
            Err(e) => rows.push(vec![
                format!("={mu}"),
                format!("not computed: {e}"),
                String::new(),
                String::new(),
                String::new(),
                String::new(),
            ]),
        }
    }
    Table {
        id: "friction-events".into(),
        title: "Events of the main case with Coulomb friction".into(),
        intro: format!(
            "The main case (identical solid cylinders, from rest at θ₀ = {THETA0}) with the same coefficient μ \
             (static = kinetic) at the floor and between the cylinders. Every time and angle is printed with \
             its verified digits. The floor never slips in these three cases; at μ = 10 no sliding continuation \
             is consistent when the contact reaches its cone, and the cylinders part there with N₁₂ > 0 just \
             before (project README, \"Where the motion is not unique\")."
        ),
        header: vec![
            "μ".into(),
            "event".into(),
            "contact".into(),
            "t".into(),
            "θ [rad]".into(),
            "mode entered".into(),
        ],
        rows,
        csv: "friction-events.csv".into(),
    }
}

/// Shading of sliding at each contact.
const SLIP_CONTACT: (u8, u8, u8) = (253, 226, 196);
const SLIP_FLOOR: (u8, u8, u8) = (226, 214, 240);
const SLIP_BOTH: (u8, u8, u8) = (240, 214, 214);

/// The phases of a track as shaded bands: which contact slips, and flight.
fn phase_bands(tr: &Track) -> Vec<Band> {
    let mut out = Vec::new();
    let mut k = 0;
    while k < tr.rows.len() {
        let ph = &tr.phases[k];
        let mut j = k;
        while j + 1 < tr.rows.len() && tr.phases[j + 1] == *ph {
            j += 1;
        }
        // the phase runs from the event before its first row to the event after its last
        let t0 = tr
            .events
            .iter()
            .rev()
            .find(|e| e.t <= tr.rows[k][0])
            .map_or(0.0, |e| e.t);
        let t1 = tr
            .events
            .iter()
            .find(|e| e.t >= tr.rows[j][0])
            .map_or(tr.rows[j][0], |e| e.t);
        let (floor, contact) = ph.split_once('/').unwrap_or((ph.as_str(), ""));
        let color = if ph == "flight" {
            Some((super::fig_main::FLIGHT, "flight"))
        } else {
            match (floor.starts_with("slip"), contact.starts_with("slip")) {
                (true, true) => Some((SLIP_BOTH, "both contacts slide")),
                (false, true) => Some((SLIP_CONTACT, "the cylinders slide on each other")),
                (true, false) => Some((SLIP_FLOOR, "cylinder 1 slides on the floor")),
                _ => None,
            }
        };
        if let Some((c, what)) = color {
            out.push(Band {
                x: (t0, t1),
                color: c,
                title: format!("{what} ({ph}), t = {} to {}", fmt(t0, 4), fmt(t1, 4)),
            });
        }
        k = j + 1;
    }
    out
}

fn ev_name(e: &super::track::Ev) -> String {
    let k = e.kind.name().replace('_', " ");
    if e.which.is_empty() {
        k
    } else {
        format!(
            "{k} ({})",
            if e.which == "contact" {
                "cylinders"
            } else {
                "floor"
            }
        )
    }
}

/// The section's figures.
pub fn figures(d: &FrictionData, digits: u32) -> Vec<Figure> {
    let mut figs = Vec::new();
    if let Ok(tr) = &d.traj {
        figs.push(friction_main(tr, digits));
    }
    if !d.map.is_empty() {
        figs.push(friction_map(d, digits));
    }
    if !d.plane.0.is_empty() {
        figs.push(friction_plane(d, digits));
    }
    figs
}

/// The main case with μ = 0.3: θ with its events, the forces between the
/// cylinders with the cone, the slip speeds, the work of friction.
fn friction_main(tr: &Track, digits: u32) -> Figure {
    let d = Digits::Verified(digits);
    let bands = phase_bands(tr);
    let lines = |label: bool| -> Vec<RefLine> {
        tr.events
            .iter()
            .filter(|e| e.kind != Kind::Impact)
            .map(|e| {
                let l = if !label {
                    String::new()
                } else if e.kind == Kind::Separation {
                    format!("tₛ = {}", fmt(e.t, 3))
                } else {
                    format!("{}: t = {}", e.kind.name().replace('_', " "), fmt(e.t, 3))
                };
                let mut r = if e.kind == Kind::Separation {
                    sep_line(e.t, if label { l } else { String::new() }, d)
                } else {
                    RefLine::vertical(e.t, Dash::DashDot, l)
                        .verified(d, format!("{} at t = {}", ev_name(e), fmt(e.t, 4)))
                };
                r.key = format!("{};contact={}", e.kind.name(), e.which);
                r.title = format!(
                    "{} at t = {}, θ = {}",
                    ev_name(e),
                    fmt(e.t, 4),
                    fmt(e.theta, 4)
                );
                r
            })
            .collect()
    };
    let series = |name: &str, col: &str, color, dash, label: &str| {
        let (pts, ph) = tr.col(col);
        Series::new(label, color, pts)
            .csv(format!("curve={name}"), Some(Quantity::new(col, "", "")))
            .phases(ph)
            .dashed(dash)
            .digits(Digits::Exact, d)
    };
    let mut p1 = Panel::new("θ, with its events", q_t(), q_theta());
    let mut s = series("theta", "theta", PALETTE[0], Dash::Solid, "");
    s.yq = None;
    p1.series.push(s);
    p1.markers = tr
        .events
        .iter()
        .map(|e| {
            Marker::new(
                Shape::Diamond,
                (e.t, e.theta),
                PALETTE[6],
                format!(
                    "{} at t = {}, θ = {}",
                    ev_name(e),
                    fmt(e.t, 4),
                    fmt(e.theta, 4)
                ),
            )
            .key(format!("event={}", e.kind.name()))
            .digits(d)
        })
        .collect();
    let mut p2 = Panel::new("forces between the cylinders", q_t(), q_force());
    let (n12, ph) = tr.col("N12");
    let cone: Vec<(f64, f64)> = n12.iter().map(|&(t, n)| (t, 0.3 * n)).collect();
    let ncone: Vec<(f64, f64)> = cone.iter().map(|&(t, c)| (t, -c)).collect();
    p2.series = vec![
        series("N12", "N12", PALETTE[2], Dash::Solid, "N₁₂")
            .shape(Shape::Circle)
            .every(9, 2),
        series("F21", "F21", PALETTE[1], Dash::Dashed, "F₂₁")
            .shape(Shape::Square)
            .every(9, 6),
        Series::new("±μN₁₂, the friction cone", PALETTE[6], cone)
            .csv("curve=mu_N12", Some(Quantity::new("mu_N12", "m1*g", "")))
            .phases(ph.clone())
            .dashed(Dash::Dotted)
            .digits(Digits::Exact, d),
        Series::new("", PALETTE[6], ncone)
            .csv(
                "curve=minus_mu_N12",
                Some(Quantity::new("minus_mu_N12", "m1*g", "")),
            )
            .phases(ph)
            .dashed(Dash::Dotted)
            .digits(Digits::Exact, d),
    ];
    let q_slip = Quantity::new("slip_speed", "sqrt(r1*g)", "slip speed (√(r₁g))");
    let mut p3 = Panel::new("slip speeds", q_t(), q_slip);
    p3.series = vec![
        series(
            "s12",
            "s12",
            PALETTE[3],
            Dash::Solid,
            "s₁₂: between the cylinders",
        ),
        series("s1", "s1", PALETTE[4], Dash::Dashed, "s₁: at the floor"),
    ];
    // a slip speed belongs to a contact: none in flight (each curve ends at
    // its value at separation)
    for sr in &mut p3.series {
        for (q, ph) in sr.points.iter_mut().zip(&sr.phases) {
            if ph == "flight" {
                *q = (f64::NAN, f64::NAN);
            }
        }
    }
    let mut p4 = Panel::new(
        "energy dissipated, W = E(0) − E(t)",
        q_t(),
        Quantity::new("work", "m1*g*r1", "W (m₁gr₁)"),
    );
    p4.series
        .push(series("work", "work", PALETTE[5], Dash::Solid, ""));
    for (k, p) in [&mut p1, &mut p2, &mut p3, &mut p4].into_iter().enumerate() {
        p.bands = bands.clone();
        p.lines = lines(k == 0);
        for s in &mut p.series {
            if s.yq.as_ref().is_some_and(|q| q.unit.is_empty()) {
                let name = s.yq.as_ref().map(|q| q.name.clone()).unwrap_or_default();
                s.yq = Some(Quantity::new(&name, &p.yq.unit, ""));
            }
        }
    }
    let evtext: Vec<String> = tr
        .events
        .iter()
        .map(|e| {
            format!(
                "{} at t = {}, θ = {}",
                ev_name(e),
                fmt(e.t, 4),
                rad(e.theta, 4)
            )
        })
        .collect();
    let mut f = Figure::new(
        "friction_main",
        format!("The main case with μ = 0.3 at both contacts, from rest at θ₀ = {THETA0}"),
        vec![p1, p2, p3, p4],
        2,
    )
    .heights(150.0, 150.0);
    f.share_x = true;
    f.legend = vec![
        LegendEntry::marker("event", PALETTE[6], Shape::Diamond, true, order::MARK),
        LegendEntry::line(
            "slip onset (dash-dot line)",
            REF,
            Dash::DashDot,
            order::BRANCH - 1,
        ),
        LegendEntry::line("separation", REF, Dash::Dotted, order::SEPARATION),
        LegendEntry::swatch("the cylinders slide on each other", SLIP_CONTACT),
        LegendEntry::swatch("cylinder 1 slides on the floor", SLIP_FLOOR),
        LegendEntry::swatch("flight to the first impact", super::fig_main::FLIGHT),
    ];
    let slides_floor = tr
        .phases
        .iter()
        .any(|p| p.split_once('/').is_some_and(|x| x.0.starts_with("slip")));
    if !slides_floor {
        f.legend.retain(|e| e.color != SLIP_FLOOR);
    }
    f.caption(format!(
        "The main case with the same Coulomb coefficient μ = 0.3 (static = kinetic) at the floor and between the cylinders. Events: {}. Shading tells which contact slides: orange, the cylinders on each other (F₂₁ = −μN₁₂ on the cone); {}blue, the free flight after separation to the first impact. Every event time is a sample point and the lines break at every phase boundary: N₁₂ reaches 0 at tₛ, the slip speeds end at their values there (there is no contact, and no slip speed, in flight), and in flight F₂₁ = N₁₂ = 0 and W stays constant. {UNITS}",
        evtext.join("; "),
        if slides_floor { "violet, cylinder 1 on the floor; " } else { "the floor never slides here; " }
    ))
}

/// Where slip starts (and at which contact) and where the cylinders part,
/// over μ.
fn friction_map(d: &FrictionData, digits: u32) -> Figure {
    let dg = Digits::Verified(digits);
    let q_mu = Quantity::new("mu", "1", "μ at both contacts (log scale)");
    let mut p = Panel::new("", q_mu, q_theta());
    p.xlog = true;
    let ths: Vec<(f64, f64)> = d.map.iter().map(|m| (m.0, m.2)).collect();
    let onset = |w: &str| -> Vec<(f64, f64)> {
        d.map
            .iter()
            .map(|m| match &m.1 {
                Some((o, c)) if c == w => (m.0, *o),
                _ => (f64::NAN, f64::NAN),
            })
            .collect()
    };
    let mut s_ths = Series::new("θₛ with friction", PALETTE[0], ths)
        .csv("theta_s", None)
        .shape(Shape::Circle)
        .digits(Digits::Exact, dg);
    s_ths.every = 4;
    s_ths.offset = 1;
    let mut s_c = Series::new(
        "first slip onset: the cylinders",
        PALETTE[1],
        onset("contact"),
    )
    .csv("first_slip;contact=cylinders", None)
    .shape(Shape::TriangleDown)
    .digits(Digits::Exact, dg);
    s_c.dash = Dash::Dashed;
    s_c.every = 1;
    let mut s_f = Series::new("first slip onset: the floor", PALETTE[4], onset("floor"))
        .csv("first_slip;contact=floor", None)
        .shape(Shape::Triangle)
        .digits(Digits::Exact, dg);
    s_f.dash = Dash::Dashed;
    s_f.every = 1;
    p.series = vec![s_ths, s_c, s_f];
    p.lines.push(
        RefLine::horizontal(d.ideal[0], PALETTE[6], Dash::Dotted, "μ = ∞")
            .verified(
                dg,
                format!("both contacts rolling (μ = ∞): θₛ = {}", fmt(d.ideal[0], 6)),
            )
            .key("theta_s;model=roll/roll"),
    );
    p.lines.push(
        RefLine::horizontal(d.ideal[1], PALETTE[2], Dash::Dotted, "μ = 0")
            .verified(
                dg,
                format!(
                    "both contacts frictionless (μ = 0): θₛ = {}",
                    fmt(d.ideal[1], 6)
                ),
            )
            .key("theta_s;model=slip/slip"),
    );
    p.markers = d
        .map
        .iter()
        .filter(|m| m.3)
        .map(|m| {
            Marker::new(
                Shape::Diamond,
                (m.0, m.2),
                PALETTE[3],
                format!(
                    "μ = {}: the contact opens at θ = {} with N₁₂ > 0",
                    fmt(m.0, 3),
                    fmt(m.2, 4)
                ),
            )
            .key(format!("opens_at_cone;mu={}", super::csv::num(m.0, 6)))
            .digits(dg)
        })
        .collect();
    let mut f = Figure::new("friction_map", format!("The main case from θ₀ = {THETA0}: where slip starts, at which contact, and where the cylinders part"), vec![p], 1)
        .heights(200.0, 180.0);
    if !f.panels[0].markers.is_empty() {
        f.legend.push(LegendEntry::marker(
            "the contact opens at an event, N₁₂ > 0",
            PALETTE[3],
            Shape::Diamond,
            true,
            order::MARK,
        ));
    }
    f.legend.push(LegendEntry::line(
        "θₛ of the ideal limits: μ = ∞ (rolling), μ = 0 (frictionless)",
        PALETTE[6],
        Dash::Dotted,
        order::LIMIT,
    ));
    let failed = if d.map_failed.is_empty() {
        String::new()
    } else {
        let mus: Vec<String> = d.map_failed.iter().map(|(m, _)| fmt(*m, 3)).collect();
        format!(
            " Not computed (no unique continuation of the rigid-body model): μ = {}.",
            mus.join(", ")
        )
    };
    let floor_mus: Vec<String> = d
        .map
        .iter()
        .filter(|m| m.1.as_ref().is_some_and(|o| o.1 == "floor"))
        .map(|m| fmt(m.0, 3))
        .collect();
    let floor_text = if floor_mus.is_empty() {
        "The cylinders always slip first.".to_string()
    } else {
        format!("The floor slips first (upward triangles) at μ = {}; elsewhere the cylinders do (downward triangles), so the first onset jumps between the two curves where the contact that slips first changes.", floor_mus.join(", "))
    };
    f.caption(format!(
        "The same coefficient at both contacts, {} values from 0.01 to 100. {floor_text} As μ → ∞ the slip onset and θₛ approach the rolling model's θₛ = {}; as μ → 0 slip starts at once and θₛ approaches the frictionless model's {}. Diamonds: the contact opens at an event while N₁₂ > 0 (no closed mode is consistent there).{failed} Angles in radians.",
        d.map.len() + d.map_failed.len(),
        rad(d.ideal[0], 6),
        rad(d.ideal[1], 6)
    ))
}

/// θs over (μ_floor, μ_contact): one cell per computed point.
fn friction_plane(d: &FrictionData, digits: u32) -> Figure {
    let (gx, rows) = &d.plane;
    // the colour scale spans the values and the ideal limits marked on its bar
    let vals = rows
        .iter()
        .flatten()
        .flatten()
        .copied()
        .chain([d.ideal[0], d.ideal[2]])
        .filter(|v| v.is_finite());
    let lo = vals.clone().fold(f64::INFINITY, f64::min);
    let hi = vals.fold(f64::NEG_INFINITY, f64::max).max(lo + 1e-9);
    let q_f = Quantity::new("mu_floor", "1", "μ at the floor (log scale)");
    let q_c = Quantity::new("mu_contact", "1", "μ between the cylinders (log scale)");
    let mut p = Panel::new("", q_f, q_c);
    p.xlog = true;
    p.ylog = true;
    p.grid = false;
    let lg: Vec<f64> = gx.iter().map(|x| x.log10()).collect();
    let e = super::axes::cell_edges(&lg);
    let mut recs = Vec::new();
    for (j, row) in rows.iter().enumerate() {
        for (i, v) in row.iter().enumerate() {
            let ((x0, x1), (y0, y1)) = ((e[i], e[i + 1]), (e[j], e[j + 1]));
            p.patches.push(Patch {
                outline: vec![(x0, y0), (x1, y0), (x1, y1), (x0, y1)],
                color: v.map_or((200, 200, 200), |v| viridis((v - lo) / (hi - lo))),
                title: format!(
                    "μ floor = {}, μ contact = {}: {}",
                    fmt(gx[i], 3),
                    fmt(gx[j], 3),
                    v.map_or("no unique continuation".into(), |v| format!(
                        "θₛ = {}",
                        fmt(v, 4)
                    ))
                ),
            });
            if let Some(v) = v {
                recs.push(super::csv::Record {
                    case: format!(
                        "mu_floor={};mu_contact={}",
                        super::csv::num(gx[i], 6),
                        super::csv::num(gx[j], 6)
                    ),
                    point: None,
                    phase: String::new(),
                    quantity: "theta_s".into(),
                    unit: "rad".into(),
                    value: super::csv::num(*v, digits as usize),
                    digits: digits.to_string(),
                });
            }
        }
    }
    let (a, b) = (e[0], e[lg.len()]);
    p.xrange = Some((10f64.powf(a), 10f64.powf(b)));
    p.yrange = Some((10f64.powf(a), 10f64.powf(b)));
    let missing = rows.iter().flatten().filter(|v| v.is_none()).count();
    let mut f = Figure::new("friction_plane", format!("Separation angle of the main case over (μ at the floor, μ between the cylinders), from θ₀ = {THETA0}"), vec![p], 1)
        .heights(230.0, 210.0);
    f.colorbar = Some(ColorBar {
        label: "θₛ (rad)".into(),
        range: (lo, hi),
        marks: vec![
            (d.ideal[0], "roll/roll".into()),
            (d.ideal[2], "roll/slip".into()),
        ],
        steps: Vec::new(),
    });
    f.extra_csv.push(
        super::csv::write(&recs)
            .lines()
            .skip(1)
            .map(|l| format!("{l}\n"))
            .collect(),
    );
    let grey = if missing > 0 {
        format!(
            " Grey: {missing} point{} with no unique continuation of the rigid-body model.",
            if missing == 1 { "" } else { "s" }
        )
    } else {
        String::new()
    };
    f.caption(format!(
        "θₛ (colour, radians) on a {n} × {n} grid of coefficients from 0.01 to 100 (static = kinetic), one cell per computed point (hover for its value). The marks on the colour bar are the ideal models' θₛ: both contacts rolling, roll/roll ({}), approached towards the top-right corner, and a rolling floor under a frictionless contact, roll/slip ({}), towards the bottom-right corner.{grey}",
        rad(d.ideal[0], 4),
        rad(d.ideal[2], 4),
        n = gx.len()
    ))
}
