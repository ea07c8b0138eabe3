//! The report's figures, built from [`Data`] as [`Figure`] values.

use super::data::{
    k2_grid, log_grid, text_f64, variant_name, variant_stem, Data, FloorKey, PlaneKey, ThetaCurve,
    TimeCurve, PLANE_K2, PLANE_TABLE_RATIOS, THETA0_TIME, VARIANTS,
};
use super::plot::{
    contour, nice_ticks, viridis, Cell, ColorBar, Dash, Figure, Marker, Panel, Scale, Series,
    PALETTE,
};
use super::Config;
use crate::model::{Contact, Floor};

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

const FORCE_NAMES: [&str; 4] = ["F1", "N1", "F21", "N12"];
const FORCE_LONG: [&str; 4] = [
    "F1: horizontal force of the floor on cylinder 1",
    "N1: normal force of the floor on cylinder 1",
    "F21: friction force of cylinder 1 on cylinder 2",
    "N12: normal force between the cylinders",
];

/// Time unit text.
pub const TAU: &str = "τ = √(r1/g)";
const T_LABEL: &str = "t  [τ]";
const THETA_LABEL: &str = "θ  [rad]";
const FORCE_LABEL: &str = "force  [m1 g]";
const SEP_LABEL: &str = "separation\n(N12 = 0)";

fn variant_color(v: usize) -> (u8, u8, u8) {
    PALETTE[v % PALETTE.len()]
}

fn variant_dash(v: usize) -> Dash {
    if VARIANTS[v].0 == Floor::Fixed {
        Dash::Dashed
    } else {
        Dash::Solid
    }
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

fn end_marker(pts: &[(f64, f64)], color: (u8, u8, u8)) -> Vec<Marker> {
    pts.last()
        .map(|&at| vec![Marker { at, color }])
        .unwrap_or_default()
}

fn time_panel(
    title: &str,
    ylabel: &str,
    curves: &[(usize, &TimeCurve)],
    col: usize,
    legend: bool,
) -> Panel {
    let mut p = Panel::new(title, T_LABEL, ylabel);
    for &(v, c) in curves {
        let pts = column(&c.rows, T, col);
        p.markers.extend(end_marker(&pts, variant_color(v)));
        let label = if legend {
            variant_name(VARIANTS[v])
        } else {
            String::new()
        };
        p.series
            .push(Series::new(label, variant_color(v), pts).dashed(variant_dash(v)));
    }
    p.marker_label = Some(SEP_LABEL.to_string());
    p
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
    format!("from rest at θ0 = {THETA0_TIME}")
}

/// All figures, in page order.
pub fn figures(data: &Data, cfg: &Config) -> Vec<Figure> {
    let mut figs = Vec::new();
    let times = ok_time(data);
    let thetas = ok_theta(data);
    let main_t: Vec<(usize, &TimeCurve)> = times.iter().copied().filter(|(v, _)| *v == 0).collect();
    let main_a: Vec<(usize, &ThetaCurve)> =
        thetas.iter().copied().filter(|(v, _)| *v == 0).collect();
    let units = format!(
        "Identical solid cylinders, m1 = m2 = r1 = r2 = g = 1, k1 = k2 = 1/2; time unit {TAU}, forces in units of m1 g."
    );

    // --- main case: kinematics
    if !main_t.is_empty() {
        let panels = vec![
            time_panel(
                "θ(t): line of centres from vertical",
                THETA_LABEL,
                &main_t,
                TH,
                true,
            ),
            time_panel("dθ/dt", "dθ/dt  [rad/τ]", &main_t, THD, false),
            time_panel(
                "φ1(t): rotation of cylinder 1",
                "φ1  [rad]",
                &main_t,
                PHI1,
                false,
            ),
            time_panel(
                "φ2(t): the paper's angle of cylinder 2",
                "φ2  [rad]",
                &main_t,
                PHI2,
                false,
            ),
        ];
        figs.push(Figure {
            file: "main_kinematics.svg".into(),
            title: format!("Main case (both contacts rolling), {}", start_text()),
            size: (1200, 860),
            grid: (2, 2),
            panels,
            strip: 200,
            colorbar: None,
            caption: format!(
                "θ, dθ/dt, φ1 and φ2 against time for the paper's main case (§2), {} \
                 (from exactly θ0 = 0 every time would be infinite). The dot marks separation, where N12 = 0. \
                 The paper (after eq. 18) notes that dφ1/dt and dθ/dt have opposite signs until cos θ = k2, here \
                 θ = π/3, which is exactly θs, and φ1 and θ until sin θ = k2 θ, here θ ≈ 1.90, after separation: \
                 so φ1 < 0 throughout, and dφ1/dt → 0 at separation. {units}",
                start_text()
            ),
        });
    }

    // --- main case: forces against t and θ
    if let Some(&(_, c)) = main_t.first() {
        let mut p = Panel::new("Forces against time", T_LABEL, FORCE_LABEL);
        for (i, &col) in TF.iter().enumerate() {
            let pts = column(&c.rows, T, col);
            p.markers.extend(end_marker(&pts, PALETTE[i]));
            p.series.push(Series::new(FORCE_NAMES[i], PALETTE[i], pts));
        }
        p.marker_label = Some(SEP_LABEL.into());
        figs.push(Figure {
            file: "main_forces_t.svg".into(),
            title: format!("Main case: contact forces, {}", start_text()),
            size: (1000, 560),
            grid: (1, 1),
            panels: vec![p],
            strip: 200,
            colorbar: None,
            caption: format!(
                "The four contact forces against time, main case, {}. {}; {}; {}; {}. {units}",
                start_text(),
                FORCE_LONG[0],
                FORCE_LONG[1],
                FORCE_LONG[2],
                FORCE_LONG[3]
            ),
        });
    }
    if let Some(&(_, c)) = main_a.first() {
        let mut p = Panel::new("Forces against θ", THETA_LABEL, FORCE_LABEL);
        for (i, &col) in AF.iter().enumerate() {
            let pts = column(&c.rows, 0, col);
            p.markers.extend(end_marker(&pts, PALETTE[i]));
            p.series.push(Series::new(FORCE_NAMES[i], PALETTE[i], pts));
        }
        p.marker_label = Some(SEP_LABEL.into());
        figs.push(Figure {
            file: "main_forces_theta.svg".into(),
            title: "Main case: contact forces against θ, from rest at the top".into(),
            size: (1000, 560),
            grid: (1, 1),
            panels: vec![p],
            strip: 200,
            colorbar: None,
            caption: format!(
                "The contact forces against the angle θ, main case, started from rest at the top \
                 (the limit θ0 → 0+, which the forces at a given θ have). At the top N1 = 2 (the weight of both) and \
                 N12 = 1 (the upper cylinder's weight). Separation at θs = π/3. {units}"
            ),
        });

        // friction needed
        let mut p = Panel::new(
            "Friction coefficient needed for rolling",
            THETA_LABEL,
            "μ needed",
        );
        let floor = column(&c.rows, 0, MU_FLOOR);
        let cont = column(&c.rows, 0, MU_CONTACT);
        p.series
            .push(Series::new("|F1| / N1 (floor)", PALETTE[0], floor));
        p.series.push(Series::new(
            "|F21| / N12 (between\nthe cylinders)",
            PALETTE[1],
            cont,
        ));
        let ths = c.sep.theta_s.value.to_f64();
        p.series.push(
            Series::new("θs = π/3", PALETTE[6], vec![(ths, 0.0), (ths, 1.0)]).dashed(Dash::Dashed),
        );
        p.yrange = Some((0.0, 1.0));
        p.xrange = Some((0.0, 1.1));
        figs.push(Figure {
            file: "main_friction.svg".into(),
            title: "Main case: friction coefficient needed, from rest at the top".into(),
            size: (1000, 560),
            grid: (1, 1),
            panels: vec![p],
            strip: 200,
            colorbar: None,
            caption: "The friction coefficients that rolling without slipping needs: |F1|/N1 at the floor and \
                      |F21|/N12 between the cylinders, main case, from rest at the top. F21 stays finite while N12 → 0, \
                      so the coefficient needed between the cylinders grows without bound as θ → θs: for any finite μ \
                      the upper cylinder slips before it separates (table \"Where rolling first fails\"). \
                      The axis is cut at μ = 1. The floor's coefficient passes through zero where F1 changes sign."
                .into(),
        });
    }

    // --- all contact models overlaid: kinematics
    if !times.is_empty() {
        let panels = vec![
            time_panel("θ(t)", THETA_LABEL, &times, TH, true),
            time_panel("dθ/dt", "dθ/dt  [rad/τ]", &times, THD, true),
            time_panel("φ1(t)", "φ1  [rad]", &times, PHI1, true),
            time_panel("φ2(t)", "φ2  [rad]", &times, PHI2, true),
        ];
        figs.push(Figure {
            file: "variants_kinematics.svg".into(),
            title: format!("All contact models: θ, dθ/dt, φ1, φ2, {}", start_text()),
            size: (1200, 860),
            grid: (2, 2),
            panels,
            strip: 230,
            colorbar: None,
            caption: format!(
                "The six contact models overlaid (identical solid cylinders, {}). Dashed: the lower cylinder held \
                 fixed, where φ1 = 0 throughout. Each curve ends at its own separation (dot). {units}",
                start_text()
            ),
        });
    }

    // --- all contact models overlaid: forces against t and θ
    for (against_t, file) in [
        (true, "variants_forces_t.svg"),
        (false, "variants_forces_theta.svg"),
    ] {
        let mut panels = Vec::new();
        let mut omitted = Vec::new();
        for (i, name) in FORCE_NAMES.iter().enumerate() {
            let xlabel = if against_t { T_LABEL } else { THETA_LABEL };
            let mut p = Panel::new(*name, xlabel, FORCE_LABEL);
            let mut add = |v: usize, pts: Vec<(f64, f64)>| {
                if force_is_zero(v, i) {
                    if i == 0 || i == 2 {
                        let s = format!("{name} for {}", variant_name(VARIANTS[v]));
                        omitted.push(s);
                    }
                    return;
                }
                p.markers.extend(end_marker(&pts, variant_color(v)));
                p.series.push(
                    Series::new(variant_name(VARIANTS[v]), variant_color(v), pts)
                        .dashed(variant_dash(v)),
                );
            };
            if against_t {
                for &(v, c) in &times {
                    add(v, column(&c.rows, T, TF[i]));
                }
            } else {
                for &(v, c) in &thetas {
                    add(v, column(&c.rows, 0, AF[i]));
                }
            }
            p.marker_label = Some(SEP_LABEL.into());
            panels.push(p);
        }
        let (title, start) = if against_t {
            (
                format!("All contact models: forces against time, {}", start_text()),
                start_text(),
            )
        } else {
            (
                "All contact models: forces against θ, from rest at the top".to_string(),
                "from rest at the top (θ0 → 0+)".to_string(),
            )
        };
        figs.push(Figure {
            file: file.into(),
            title,
            size: (1200, 860),
            grid: (2, 2),
            panels,
            strip: 230,
            colorbar: None,
            caption: format!(
                "F1, N1, F21, N12 for the six contact models, {start}. A force at a frictionless contact is \
                 exactly zero and is not drawn ({}). With the lower cylinder fixed (dashed), F1 and N1 are the \
                 forces of its holder. {units}",
                omitted.join("; ")
            ),
        });
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
            for (i, &col) in TF.iter().enumerate() {
                if force_is_zero(v, i) {
                    continue;
                }
                let pts = column(&c.rows, T, col);
                p.markers.extend(end_marker(&pts, PALETTE[i]));
                p.series.push(Series::new(FORCE_NAMES[i], PALETTE[i], pts));
            }
        }
        p.marker_label = Some(SEP_LABEL.into());
        panels.push(p);
        let mut p = Panel::new("against θ, from rest at the top", THETA_LABEL, FORCE_LABEL);
        if let Some(c) = ac {
            for (i, &col) in AF.iter().enumerate() {
                if force_is_zero(v, i) {
                    continue;
                }
                let pts = column(&c.rows, 0, col);
                p.markers.extend(end_marker(&pts, PALETTE[i]));
                p.series.push(Series::new(FORCE_NAMES[i], PALETTE[i], pts));
            }
        }
        p.marker_label = Some(SEP_LABEL.into());
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
            " F1 and N1 are the forces of the holder that keeps cylinder 1 still."
        } else {
            ""
        };
        figs.push(Figure {
            file: format!("variant_{}.svg", variant_stem(*variant)),
            title: format!("{}: contact forces", variant_name(*variant)),
            size: (1300, 560),
            grid: (1, 2),
            panels,
            strip: 150,
            colorbar: None,
            caption: format!(
                "Contact forces for {} ({}), against time {} and against θ from rest at the top.{zero_text}{holder} {units}",
                variant_name(*variant),
                super::data::paper_ref(*variant),
                start_text()
            ),
        });
    }

    figs.extend(plane_figures(data, cfg));
    figs
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

fn plane_figures(data: &Data, cfg: &Config) -> Vec<Figure> {
    let pd = cfg.plot_digits;
    let mut figs = Vec::new();
    let plane_text = "Both contacts rolling, from rest at the top; m1 = r1 = r2 = g = 1, k1 = 1/2 (a solid lower cylinder).";

    // θs against m2/m1 for several k2, with the fixed-lower limits
    let ratios = log_grid(cfg.ratio_range.0, cfg.ratio_range.1, cfg.ratio_per_decade);
    let mut p = Panel::new(
        "θs against the mass ratio",
        "m2 / m1  (log scale)",
        "θs  [rad]",
    );
    p.xscale = Scale::Log;
    p.xrange = Some((text_f64(&ratios[0]), text_f64(&ratios[ratios.len() - 1])));
    for (j, k2) in PLANE_K2.iter().enumerate() {
        let pts: Vec<(f64, f64)> = ratios
            .iter()
            .filter_map(|r| Some((text_f64(r), plane_value(data, FloorKey::Roll, r, k2, pd)?)))
            .collect();
        p.series
            .push(Series::new(format!("k2 = {k2}"), PALETTE[j], pts));
        let lim = fixed_closed_form(text_f64(k2));
        let (a, b) = p.xrange.unwrap_or((0.01, 100.0));
        p.series
            .push(Series::new("", PALETTE[j], vec![(a, lim), (b, lim)]).dashed(Dash::Dashed));
    }
    p.series.push(
        Series::new(
            "fixed lower cylinder:\narccos(2/(3 + k2))",
            PALETTE[6],
            vec![],
        )
        .dashed(Dash::Dashed),
    );
    figs.push(Figure {
        file: "plane_ratio.svg".into(),
        title: "Separation angle over the mass ratio, for several k2".into(),
        size: (1100, 620),
        grid: (1, 1),
        panels: vec![p],
        strip: 210,
        colorbar: None,
        caption: format!(
            "θs against m2/m1 (log scale) for k2 = {}. Dashed, in the same colour: the fixed-lower-cylinder value \
             arccos(2/(3 + k2)) of eq. (36), the limit m2/m1 → 0. k2 = 1 is a thin-walled tube, k2 = 2 a bobbin. {plane_text}",
            PLANE_K2.join(", ")
        ),
    });

    // θs against k2 for several m2/m1, with the fixed-lower curve
    let ks = k2_grid(cfg.k2_steps);
    let mut p = Panel::new("θs against k2", "k2 = I2 / (m2 r2²)", "θs  [rad]");
    p.xrange = Some((0.0, 2.0));
    for (j, r) in PLANE_TABLE_RATIOS.iter().enumerate() {
        let pts: Vec<(f64, f64)> = ks
            .iter()
            .filter_map(|k| Some((text_f64(k), plane_value(data, FloorKey::Roll, r, k, pd)?)))
            .collect();
        p.series
            .push(Series::new(format!("m2/m1 = {r}"), PALETTE[j], pts));
    }
    let curve: Vec<(f64, f64)> = (0..=200)
        .map(|i| {
            let k = 2.0 * f64::from(i) / 200.0;
            (k, fixed_closed_form(k))
        })
        .collect();
    p.series.push(
        Series::new(
            "fixed lower cylinder,\narccos(2/(3 + k2))",
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
            });
        }
    }
    p.marker_label = Some("oracle, fixed lower\ncylinder".into());
    figs.push(Figure {
        file: "plane_k2.svg".into(),
        title: "Separation angle over k2, for several mass ratios".into(),
        size: (1100, 620),
        grid: (1, 1),
        panels: vec![p],
        strip: 210,
        colorbar: None,
        caption: format!(
            "θs against k2 for m2/m1 = {}. Black dashed: the closed form arccos(2/(3 + k2)) for a fixed lower \
             cylinder (eq. 36); the open circles on it are the oracle's values for a fixed lower cylinder. {plane_text}",
            PLANE_TABLE_RATIOS.join(", ")
        ),
    });

    // heat map over (m2/m1, k2)
    let hr = log_grid(
        cfg.heat_ratio_range.0,
        cfg.heat_ratio_range.1,
        cfg.heat_per_decade,
    );
    let hk = k2_grid(cfg.heat_k2_steps);
    let xs: Vec<f64> = hr.iter().map(|r| text_f64(r).log10()).collect();
    let ys: Vec<f64> = hk.iter().map(|k| text_f64(k)).collect();
    let z: Vec<Vec<f64>> = hk
        .iter()
        .map(|k| {
            hr.iter()
                .map(|r| {
                    plane_value(data, FloorKey::Roll, r, k, pd)
                        .map(|v| v.to_degrees())
                        .unwrap_or(f64::NAN)
                })
                .collect()
        })
        .collect();
    let finite: Vec<f64> = z
        .iter()
        .flatten()
        .copied()
        .filter(|v| v.is_finite())
        .collect();
    let zlo = finite.iter().copied().fold(f64::INFINITY, f64::min);
    let zhi = finite.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    if zlo.is_finite() && zhi.is_finite() && xs.len() > 1 && ys.len() > 1 {
        let (ticks, step) = nice_ticks(zlo, zhi, 8);
        let lo = (zlo / step).floor() * step;
        let hi = (zhi / step).ceil() * step;
        let mid = |a: f64, b: f64| 0.5 * (a + b);
        let edge = |v: &[f64], i: usize| -> (f64, f64) {
            let a = if i == 0 {
                v[0] - 0.5 * (v[1] - v[0])
            } else {
                mid(v[i - 1], v[i])
            };
            let n = v.len();
            let b = if i + 1 == n {
                v[n - 1] + 0.5 * (v[n - 1] - v[n - 2])
            } else {
                mid(v[i], v[i + 1])
            };
            (a, b)
        };
        let mut p = Panel::new(
            "θs over the (m2/m1, k2) plane",
            "m2 / m1  (log scale)",
            "k2",
        );
        p.xscale = Scale::Log;
        p.xrange = Some((10f64.powf(xs[0]), 10f64.powf(xs[xs.len() - 1])));
        p.yrange = Some((ys[0], ys[ys.len() - 1]));
        for (j, row) in z.iter().enumerate() {
            for (i, &val) in row.iter().enumerate() {
                let (x0, x1) = edge(&xs, i);
                let (y0, y1) = edge(&ys, j);
                let color = if val.is_finite() {
                    viridis((val - lo) / (hi - lo))
                } else {
                    (200, 200, 200)
                };
                p.cells.push(Cell {
                    lo: (10f64.powf(x0), y0),
                    hi: (10f64.powf(x1), y1),
                    color,
                });
            }
        }
        for &level in &ticks {
            for seg in contour(&xs, &ys, &z, level) {
                p.series.push(Series {
                    label: String::new(),
                    color: (0, 0, 0),
                    dash: Dash::Solid,
                    width: 1,
                    points: vec![
                        (10f64.powf(seg[0].0), seg[0].1),
                        (10f64.powf(seg[1].0), seg[1].1),
                    ],
                });
            }
        }
        figs.push(Figure {
            file: "plane_heatmap.svg".into(),
            title: "Separation angle θs over the parameter plane".into(),
            size: (1000, 680),
            grid: (1, 1),
            panels: vec![p],
            strip: 110,
            colorbar: Some(ColorBar {
                label: "θs [deg]".into(),
                range: (lo, hi),
                marks: ticks.clone(),
            }),
            caption: format!(
                "θs in degrees (colour) over m2/m1 (log scale) and k2, with contour lines every {step}°; \
                 {} × {} oracle values, each cell centred on its value. {plane_text}",
                hr.len(),
                hk.len()
            ),
        });
    }
    figs
}
