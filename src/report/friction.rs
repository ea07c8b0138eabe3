//! The report's section on finite Coulomb friction: the main case's motion
//! through its phases, its events at three coefficients, and maps of the
//! slip-onset and separation angles over the coefficients, meeting the ideal
//! models at both ends.

use super::data::{log_grid, text_f64};
use super::page::Table;
use super::plot::{
    viridis, Cell, ColorBar, Dash, Figure, LegendEntry, Marker, Panel, Scale, Series, Shape,
    PALETTE,
};
use super::Config;
use crate::error::Result;
use crate::exact::Exact;
use crate::model::{Contact, Floor, Ideal, Law, Model, Params, Start};
use crate::motion::{Kind, COLUMNS};
use crate::oracle::{self, Answer as SeparationAnswer, Options, Oracle};

/// θ0 of the friction section (the main case's start).
const THETA0: &str = "1/10";

/// What the section computes.
pub struct FrictionData {
    /// (μ text, the separation answer) for the event table.
    pub cases: Vec<(String, Result<SeparationAnswer>)>,
    /// The main case at μ = 0.3: rows in [`columns`] order (f64) and modes.
    pub traj: Result<(Vec<Vec<f64>>, Vec<String>, SeparationAnswer)>,
    /// (μ, first slip onset θ, θs, the contact opened at the cone) at equal
    /// coefficients on both contacts.
    pub map: Vec<(f64, Option<f64>, f64, bool)>,
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
    let traj = (|| {
        let m = both("0.3", "0.3")?;
        let sep = separation(&m, cfg.plot_digits)?;
        let t_imp = value(&sep, "t_impact");
        // the grid ends at the impact time rounded down to 3 decimals
        let end = rug::Rational::from(((t_imp * 1000.0).floor() as i64, 1000));
        let n = cfg.time_points.max(4) as i64;
        let times: Vec<Exact> = (0..=n)
            .map(|i| Exact::rational(&end * rug::Rational::from((i, n))))
            .collect();
        let tr = oracle::trajectory(&m, &times, &Options::digits(cfg.plot_digits))?;
        let rows = tr
            .rows
            .iter()
            .map(|r| r.values.iter().map(|v| v.value.to_f64()).collect())
            .collect();
        let modes = tr.rows.iter().map(|r| r.phase.tag()).collect();
        Ok((rows, modes, sep))
    })();
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
                    .map(|e| e.theta.value.to_f64());
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
             before (project README, \"Friction\")."
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
    }
}

const SLIP_SHADE: (u8, u8, u8) = (253, 232, 206);
const FLIGHT_SHADE: (u8, u8, u8) = (214, 232, 248);

/// Shading of the phases over a panel's y range: slipping (any contact)
/// and flight.
fn phases(rows: &[Vec<f64>], modes: &[String], y: (f64, f64)) -> Vec<Cell> {
    let mut cells = Vec::new();
    let mut i = 0;
    while i + 1 < rows.len() {
        let m = &modes[i + 1];
        let color = if m == "flight" {
            Some(FLIGHT_SHADE)
        } else if m.contains("slip") {
            Some(SLIP_SHADE)
        } else {
            None
        };
        if let Some(color) = color {
            cells.push(Cell {
                lo: (rows[i][0], y.0),
                hi: (rows[i + 1][0], y.1),
                color,
                title: format!("{m}, t = {:.3} to {:.3}", rows[i][0], rows[i + 1][0]),
            });
        }
        i += 1;
    }
    cells
}

fn range(series: &[&[(f64, f64)]]) -> (f64, f64) {
    let mut lo = f64::INFINITY;
    let mut hi = f64::NEG_INFINITY;
    for s in series {
        for &(_, y) in *s {
            lo = lo.min(y);
            hi = hi.max(y);
        }
    }
    let pad = 0.06 * (hi - lo).max(1e-9);
    (lo - pad, hi + pad)
}

fn col(rows: &[Vec<f64>], c: &str) -> Vec<(f64, f64)> {
    let i = COLUMNS.iter().position(|x| *x == c).unwrap_or(0);
    rows.iter().map(|r| (r[0], r[i])).collect()
}

/// The section's figures.
pub fn figures(d: &FrictionData) -> Vec<Figure> {
    let mut figs = Vec::new();
    if let Ok((rows, modes, sep)) = &d.traj {
        figs.push(friction_main(rows, modes, sep));
    }
    if !d.map.is_empty() {
        figs.push(friction_map(d));
    }
    if !d.plane.0.is_empty() {
        figs.push(friction_plane(d));
    }
    figs
}

/// A panel against t of a trajectory with friction: its y range fitted to
/// `fit`, its phases shaded.
fn phase_panel(
    title: &str,
    ylabel: &str,
    rows: &[Vec<f64>],
    modes: &[String],
    fit: &[&[(f64, f64)]],
) -> Panel {
    let mut p = Panel::new(title, "t  [τ]", ylabel);
    let y = range(fit);
    p.yrange = Some(y);
    p.cells = phases(rows, modes, y);
    p
}

/// The main case with μ = 0.3: θ with its events, the forces between the
/// cylinders with the cone, the slip speeds, the work of friction.
fn friction_main(rows: &[Vec<f64>], modes: &[String], sep: &SeparationAnswer) -> Figure {
    let ev: Vec<(f64, f64, &str)> = sep
        .events
        .iter()
        .map(|e| (e.t.value.to_f64(), e.theta.value.to_f64(), e.kind.name()))
        .collect();
    let th = col(rows, "theta");
    let n12 = col(rows, "N12");
    let f21 = col(rows, "F21");
    let cone: Vec<(f64, f64)> = n12.iter().map(|&(t, n)| (t, 0.3 * n)).collect();
    let ncone: Vec<(f64, f64)> = cone.iter().map(|&(t, c)| (t, -c)).collect();
    let (s12, s1, work) = (col(rows, "s12"), col(rows, "s1"), col(rows, "work"));
    let mut p1 = phase_panel("θ, events marked", "θ  [rad]", rows, modes, &[&th]);
    p1.series.push(Series::new("θ", PALETTE[0], th.clone()));
    p1.markers = ev
        .iter()
        .map(|&(t, theta, k)| {
            let name = k.replace('_', " ");
            let title = format!("{name} at t = {t:.4}, θ = {theta:.4}");
            Marker::shaped(
                Shape::Diamond,
                (t, theta),
                PALETTE[6],
                title,
                Some(format!("{name}, θ = {theta:.3}")),
            )
        })
        .collect();
    p1.legend = vec![
        LegendEntry::marker(
            "event (slip onset, separation, impact)",
            PALETTE[6],
            Shape::Diamond,
            true,
        ),
        LegendEntry::marker(
            "shaded orange: the contact slips",
            SLIP_SHADE,
            Shape::Square,
            true,
        ),
        LegendEntry::marker(
            "shaded blue: free flight",
            FLIGHT_SHADE,
            Shape::Square,
            true,
        ),
    ];
    let title = "Forces between the cylinders, and the cone ±μN₁₂";
    let mut p2 = phase_panel(title, "force  [m₁g]", rows, modes, &[&n12, &f21, &ncone]);
    p2.series = vec![
        Series::new("N₁₂", PALETTE[2], n12).shape(Shape::Circle),
        Series::new("F₂₁", PALETTE[1], f21).dashed(Dash::Dashed),
        Series::new("±μN₁₂ (the friction cone)", PALETTE[6], cone).dashed(Dash::Dotted),
        Series::new("", PALETTE[6], ncone).dashed(Dash::Dotted),
    ];
    let mut p3 = phase_panel(
        "Slip speeds",
        "slip speed  [√(r₁g)]",
        rows,
        modes,
        &[&s12, &s1],
    );
    p3.series = vec![
        Series::new("s₁₂: between the cylinders", PALETTE[3], s12),
        Series::new("s₁: at the floor", PALETTE[4], s1).dashed(Dash::Dashed),
    ];
    let title = "Energy dissipated by friction, W = E(0) − E(t)";
    let mut p4 = phase_panel(title, "W  [m₁gr₁]", rows, modes, &[&work]);
    p4.series.push(Series::new("W", PALETTE[5], work));
    let evtext: Vec<String> = ev
        .iter()
        .map(|(t, th, k)| format!("{} at t = {t:.4}, θ = {th:.4}", k.replace('_', " ")))
        .collect();
    let title = format!("The main case with μ = 0.3 at both contacts, from rest at θ₀ = {THETA0}");
    Figure::new("friction_main.svg", title, (1300, 860), (2, 2), vec![p1, p2, p3, p4], 230).caption(format!(
        "Unshaded: both contacts roll; orange: the contact between the cylinders slips (s12 > 0, \
         F21 = −μ N12 on the cone); blue: free flight after separation, to the first impact (cylinder 2 \
         on the floor). Events: {}. The floor never slips (s1 = 0). In flight F21 = N12 = 0 and W stays \
         constant. Every point is an oracle value verified to the plotted digits.",
        evtext.join("; ")
    ))
}

/// Where slip starts and where the cylinders part, over μ.
fn friction_map(d: &FrictionData) -> Figure {
    let onset: Vec<(f64, f64)> = d.map.iter().filter_map(|m| m.1.map(|o| (m.0, o))).collect();
    let ths: Vec<(f64, f64)> = d.map.iter().map(|m| (m.0, m.2)).collect();
    let (x0, x1) = (0.01, 100.0);
    let level = |label: &str, color, y: f64| {
        Series::new(label, color, vec![(x0, y), (x1, y)]).dashed(Dash::Dotted)
    };
    let mut p = Panel::new("", "μ (both contacts, log scale)", "θ  [rad]");
    p.xscale = Scale::Log;
    p.xrange = Some((x0, x1));
    p.series = vec![
        Series::new("θₛ with friction", PALETTE[0], ths)
            .shape(Shape::Circle)
            .every(4, 1),
        Series::new("first slip onset (either contact)", PALETTE[1], onset)
            .shape(Shape::Square)
            .every(4, 3)
            .dashed(Dash::Dashed),
        level("θₛ rolling (μ = ∞)", PALETTE[6], d.ideal[0]),
        level("θₛ frictionless (μ = 0)", PALETTE[2], d.ideal[1]),
    ];
    p.markers = d
        .map
        .iter()
        .filter(|m| m.3)
        .map(|m| {
            let title = format!(
                "μ = {:.3}: the contact opens at θ = {:.4} with N₁₂ > 0",
                m.0, m.2
            );
            Marker::shaped(Shape::Diamond, (m.0, m.2), PALETTE[3], title, None)
        })
        .collect();
    if !p.markers.is_empty() {
        let label = "the contact opens at an event, N₁₂ > 0";
        p.legend
            .push(LegendEntry::marker(label, PALETTE[3], Shape::Diamond, true));
    }
    let failed = if d.map_failed.is_empty() {
        String::new()
    } else {
        let mus: Vec<String> = d
            .map_failed
            .iter()
            .map(|(m, _)| format!("{m:.3}"))
            .collect();
        format!(
            " Not computed (no unique continuation of the rigid-body model): μ = {}.",
            mus.join(", ")
        )
    };
    let title =
        format!("The main case from θ₀ = {THETA0}: where slip starts and where the cylinders part");
    Figure::single("friction_map.svg", title, (1100, 620), p, 250).caption(format!(
        "The same coefficient at both contacts, {} values from 0.01 to 100. As μ → ∞ the slip onset \
         and θₛ approach the rolling model's θₛ = {:.6}; as μ → 0 slip starts at once and θₛ approaches \
         the frictionless model's {:.6}. Marked: the contact opens at an event while N₁₂ > 0, because no \
         mode with the contact closed is consistent there — for large μ when the contact reaches its \
         cone close to θₛ, and elsewhere when the floor's slip stops and the floor's force jumps.{failed}",
        d.map.len() + d.map_failed.len(),
        d.ideal[0],
        d.ideal[1]
    ))
}

/// The cells of the (μ_floor, μ_contact) grid (log10 coordinates), coloured
/// over [lo, hi], and the grid's CSV.
fn plane_cells(gx: &[f64], rows: &[Vec<Option<f64>>], lo: f64, hi: f64) -> (Vec<Cell>, String) {
    let lg: Vec<f64> = gx.iter().map(|x| x.log10()).collect();
    let mut cells = Vec::new();
    let mut csv = String::from("mu_floor,mu_contact,theta_s_rad\n");
    for (j, row) in rows.iter().enumerate() {
        for (i, v) in row.iter().enumerate() {
            let ((x0, x1), (y0, y1)) = (half_cell(&lg, i), half_cell(&lg, j));
            let color = match v {
                Some(v) => viridis((v - lo) / (hi - lo).max(1e-12)),
                None => (200, 200, 200),
            };
            let value = v.map_or("no unique continuation".to_string(), |v| {
                format!("θₛ = {v:.4}")
            });
            cells.push(Cell {
                lo: (x0, y0),
                hi: (x1, y1),
                color,
                title: format!("μ_floor = {:.3}, μ_contact = {:.3}: {value}", gx[i], gx[j]),
            });
            csv.push_str(&format!(
                "{},{},{}\n",
                super::plot::csv_num(gx[i], 6),
                super::plot::csv_num(gx[j], 6),
                v.map_or(String::new(), |v| super::plot::csv_num(v, 12))
            ));
        }
    }
    (cells, csv)
}

/// The extent of grid cell `i` of the nodes `lg`: halfway to its neighbours.
fn half_cell(lg: &[f64], i: usize) -> (f64, f64) {
    let a = if i == 0 {
        lg[0] - (lg[1] - lg[0]) / 2.0
    } else {
        (lg[i - 1] + lg[i]) / 2.0
    };
    let b = if i + 1 == lg.len() {
        lg[i] + (lg[i] - lg[i - 1]) / 2.0
    } else {
        (lg[i] + lg[i + 1]) / 2.0
    };
    (a, b)
}

/// θs over (μ_floor, μ_contact).
fn friction_plane(d: &FrictionData) -> Figure {
    let (gx, rows) = &d.plane;
    let vals = rows.iter().flatten().flatten().copied();
    let lo = vals.clone().fold(f64::INFINITY, f64::min);
    let hi = vals.fold(f64::NEG_INFINITY, f64::max);
    let mut p = Panel::new(
        "",
        "log₁₀ μ_floor (the floor's coefficient)",
        "log₁₀ μ_contact (between the cylinders)",
    );
    let (cells, csv) = plane_cells(gx, rows, lo, hi);
    p.cells = cells;
    let lg: Vec<f64> = gx.iter().map(|x| x.log10()).collect();
    p.xrange = Some((half_cell(&lg, 0).0, half_cell(&lg, lg.len() - 1).1));
    p.yrange = p.xrange;
    let missing = rows.iter().flatten().filter(|v| v.is_none()).count();
    let title =
        format!("Separation angle of the main case over (μ_floor, μ_contact), from θ₀ = {THETA0}");
    let mut fig = Figure::single("friction_plane.svg", title, (900, 760), p, 150);
    fig.csv = Some(csv);
    fig.colorbar = Some(ColorBar {
        label: "θₛ [rad]".into(),
        range: (lo, hi),
        marks: vec![
            (d.ideal[0], "roll/roll".into()),
            (d.ideal[2], "roll/slip".into()),
        ],
    });
    let grey = if missing > 0 {
        format!(
            " Grey: {missing} point{} with no unique continuation of the rigid-body model.",
            if missing == 1 { "" } else { "s" }
        )
    } else {
        String::new()
    };
    fig.caption(format!(
        "θₛ (colour) on a {n} × {n} grid of coefficients from 0.01 to 100 (static = kinetic). The marks \
         on the colour bar are the ideal models' θₛ: both rolling ({:.4}, approached towards the \
         top-right corner) and a rolling floor under a frictionless contact ({:.4}, the bottom-right \
         corner).{grey}",
        d.ideal[0],
        d.ideal[2],
        n = gx.len()
    ))
}
