//! The parameter plane (m₂/m₁, k₂): θs along families of curves (two
//! panels on one θs axis) and over the whole plane (a map of the computed
//! nodes with labelled contours).

use super::csv::{self, Record};
use super::data::{
    k2_grid, log_grid, text_f64, Data, FloorKey, PlaneKey, PLANE_K2, PLANE_TABLE_RATIOS,
};
use super::fig_main::stagger;
use super::legend::viridis;
use super::model::{
    fmt, order, ColorBar, Dash, Digits, Figure, LegendEntry, Marker, Panel, Patch, Quantity,
    Series, Shape, PALETTE,
};
use super::Config;

const PLANE_TEXT: &str = "Both contacts rolling, from rest at the top; m₁ = r₁ = r₂ = g = 1, k₁ = 1/2 (a solid lower cylinder); k₂ = I₂/(m₂r₂²) is the upper cylinder's moment of inertia in units of m₂r₂² (0: a point mass on the rim's axis, 1/2: solid, 1: thin-walled tube, 2: a bobbin). Angles in radians.";

fn q_ratio() -> Quantity {
    Quantity::new("m2_over_m1", "1", "m₂/m₁ (log scale)")
}

fn q_k2() -> Quantity {
    Quantity::new("k2", "1", "k₂ = I₂/(m₂r₂²)")
}

fn q_ths() -> Quantity {
    Quantity::new("theta_s", "rad", "θₛ (rad)")
}

fn value(data: &Data, floor: FloorKey, ratio: &str, k2: &str, digits: u32) -> Option<f64> {
    let key = PlaneKey {
        floor,
        ratio: ratio.to_string(),
        k2: k2.to_string(),
        digits,
    };
    data.plane
        .get(&key)
        .and_then(|r| r.as_ref().ok())
        .map(|v| v.value.to_f64())
}

fn fixed_closed_form(k2: f64) -> f64 {
    (2.0 / (3.0 + k2)).acos()
}

/// θs against m₂/m₁ for several k₂ and against k₂ for several m₂/m₁, on
/// one θs axis.
pub fn plane_curves(data: &Data, cfg: &Config) -> Figure {
    let pd = cfg.plot_digits;
    let d = Digits::Verified(pd);
    let ratios = log_grid(cfg.ratio_range.0, cfg.ratio_range.1, cfg.ratio_per_decade);
    let xr = (text_f64(&ratios[0]), text_f64(&ratios[ratios.len() - 1]));
    let mut pa = Panel::new("(a) against the mass ratio", q_ratio(), q_ths());
    pa.xlog = true;
    pa.names_right = true;
    for (j, k2) in PLANE_K2.iter().enumerate() {
        let pts: Vec<(f64, f64)> = ratios
            .iter()
            .filter_map(|r| Some((text_f64(r), value(data, FloorKey::Roll, r, k2, pd)?)))
            .collect();
        pa.series.push(stagger(
            Series::new(format!("k₂ = {k2}"), PALETTE[j], pts)
                .csv(format!("k2={k2}"), None)
                .shape(super::model::SHAPES[j])
                .direct(format!("k₂ = {k2}"))
                .digits(Digits::Exact, d),
            j,
            PLANE_K2.len(),
        ));
        let lim = fixed_closed_form(text_f64(k2));
        pa.series.push(
            Series::new("", PALETTE[j], vec![(xr.0, lim), (xr.1, lim)])
                .csv(format!("k2={k2};held_lower_closed_form"), None)
                .dashed(Dash::Dotted)
                .digits(Digits::Exact, Digits::Double),
        );
    }
    let ks = k2_grid(cfg.k2_steps);
    let mut pb = Panel::new("(b) against k₂", q_k2(), q_ths());
    pb.names_right = true;
    for (j, r) in PLANE_TABLE_RATIOS.iter().enumerate() {
        let pts: Vec<(f64, f64)> = ks
            .iter()
            .filter_map(|k| Some((text_f64(k), value(data, FloorKey::Roll, r, k, pd)?)))
            .collect();
        pb.series.push(stagger(
            Series::new(format!("m₂/m₁ = {r}"), PALETTE[j], pts)
                .csv(format!("m2_over_m1={r}"), None)
                .shape(super::model::SHAPES[j])
                .dashed(Dash::Dashed)
                .direct(format!("m₂/m₁ = {r}"))
                .digits(Digits::Exact, d),
            j,
            PLANE_TABLE_RATIOS.len(),
        ));
    }
    let curve: Vec<(f64, f64)> = (0..=100)
        .map(|i| {
            let k = 2.0 * f64::from(i) / 100.0;
            (k, fixed_closed_form(k))
        })
        .collect();
    pb.series.push(
        Series::new("held lower cylinder: arccos(2/(3 + k₂))", PALETTE[6], curve)
            .csv("held_lower_closed_form", None)
            .dashed(Dash::Dotted)
            .digits(Digits::Double, Digits::Double),
    );
    for k in &ks {
        if let Some(v) = value(data, FloorKey::Fixed, "1", k, pd) {
            pb.markers.push(
                Marker::new(
                    Shape::Circle,
                    (text_f64(k), v),
                    PALETTE[6],
                    format!("oracle, held lower cylinder, k₂ = {k}: θₛ = {}", fmt(v, 5)),
                )
                .key(format!("held_lower;k2={k}"))
                .hollow()
                .digits(d),
            );
        }
    }
    let mut f = Figure::new(
        "plane_curves",
        "The separation angle over the mass ratio and over k₂",
        vec![pa, pb],
        2,
    )
    .heights(200.0, 175.0);
    f.share_y = true;
    f.legend.push(LegendEntry::marker(
        "oracle, held lower cylinder",
        PALETTE[6],
        Shape::Circle,
        false,
        order::MARK,
    ));
    f.legend.push(LegendEntry::line(
        "(a) dotted, in each k₂'s colour: its held-lower limit",
        PALETTE[7],
        Dash::Dotted,
        order::LIMIT,
    ));
    f.caption(format!(
        "θₛ (a) against m₂/m₁ from {} to {} (log scale) for k₂ = {}, and (b) against k₂ for m₂/m₁ = {}, on one θₛ axis. Dotted: the closed form arccos(2/(3 + k₂)) of a held lower cylinder (eq. 36), the limit m₂/m₁ → 0; in (b) the hollow circles on it are the oracle's values for a held lower cylinder. {PLANE_TEXT}",
        ratios[0],
        ratios[ratios.len() - 1],
        PLANE_K2.join(", "),
        PLANE_TABLE_RATIOS.join(", ")
    ))
}

/// θs over (m₂/m₁, k₂): each computed node a cell in its colour, with
/// contours (marching squares, interpolated between the nodes) labelled.
pub fn plane_map(data: &Data, cfg: &Config) -> Option<Figure> {
    let pd = cfg.plot_digits;
    let hr = log_grid(
        cfg.heat_ratio_range.0,
        cfg.heat_ratio_range.1,
        cfg.heat_per_decade,
    );
    let hk = k2_grid(cfg.heat_k2_steps);
    let xs: Vec<f64> = hr.iter().map(|r| text_f64(r).log10()).collect();
    let ys: Vec<f64> = hk.iter().map(|k| text_f64(k)).collect();
    if xs.len() < 2 || ys.len() < 2 {
        return None;
    }
    let z: Vec<Vec<f64>> = hk
        .iter()
        .map(|k| {
            hr.iter()
                .map(|r| value(data, FloorKey::Roll, r, k, pd).unwrap_or(f64::NAN))
                .collect()
        })
        .collect();
    let fin = z.iter().flatten().copied().filter(|v| v.is_finite());
    let lo = fin.clone().fold(f64::INFINITY, f64::min);
    let hi = fin.fold(f64::NEG_INFINITY, f64::max);
    if !(lo.is_finite() && hi > lo) {
        return None;
    }
    let mut p = Panel::new("", q_ratio(), q_k2());
    p.xlog = true;
    p.grid = false;
    // a cell reaches halfway to each neighbouring node (the nodes are not
    // quite evenly spaced in log10: their ratios are decimals)
    let (cx, cy) = (super::axes::cell_edges(&xs), super::axes::cell_edges(&ys));
    p.xrange = Some((10f64.powf(cx[0]), 10f64.powf(cx[xs.len()])));
    p.yrange = Some((cy[0], cy[ys.len()]));
    let mut records = Vec::new();
    for (j, row) in z.iter().enumerate() {
        for (i, v) in row.iter().enumerate() {
            let (x0, x1, y0, y1) = (cx[i], cx[i + 1], cy[j], cy[j + 1]);
            let color = if v.is_finite() {
                viridis((v - lo) / (hi - lo))
            } else {
                (200, 200, 200)
            };
            p.patches.push(Patch {
                outline: vec![(x0, y0), (x1, y0), (x1, y1), (x0, y1)],
                color,
                title: format!(
                    "m₂/m₁ = {}, k₂ = {}: θₛ = {}",
                    csv::num(text_f64(&hr[i]), 6),
                    hk[j],
                    fmt(*v, 5)
                ),
            });
            let case = format!("m2_over_m1={};k2={}", hr[i], hk[j]);
            records.push(Record {
                case,
                point: None,
                phase: String::new(),
                quantity: "theta_s".into(),
                unit: "rad".into(),
                value: csv::num(*v, pd as usize),
                digits: pd.to_string(),
            });
        }
    }
    // contours every nice step, from the contour crate (marching squares on
    // the nodes' indices, mapped back to the nodes' coordinates)
    let (levels, step) = super::axes::nice_ticks(lo, hi, 7);
    let dec = super::axes::decimals_for(step);
    let flat: Vec<f64> = z
        .iter()
        .flatten()
        .map(|v| if v.is_finite() { *v } else { f64::NAN })
        .collect();
    let at = |g: &[f64], u: f64| {
        let i = (u.floor().max(0.0) as usize).min(g.len() - 2);
        g[i] + (u - i as f64) * (g[i + 1] - g[i])
    };
    let builder = contour::ContourBuilder::new(xs.len(), ys.len(), true)
        .x_origin(-0.5)
        .y_origin(-0.5);
    if let Ok(lines) = builder.lines(&flat, &levels) {
        for line in lines {
            let level = line.threshold();
            for ls in line.geometry().0.iter() {
                // the rings close along the grid's border, outside the nodes:
                // keep the runs of points on or between the nodes
                let (nx, ny) = ((xs.len() - 1) as f64, (ys.len() - 1) as f64);
                let tol = 1e-9;
                let mut runs: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
                for c in &ls.0 {
                    if c.x >= -tol && c.x <= nx + tol && c.y >= -tol && c.y <= ny + tol {
                        if let Some(r) = runs.last_mut() {
                            r.push((10f64.powf(at(&xs, c.x)), at(&ys, c.y)));
                        }
                    } else if runs.last().is_some_and(|r| !r.is_empty()) {
                        runs.push(Vec::new());
                    }
                }
                for pts in runs.into_iter().filter(|r| r.len() >= 3) {
                    let mut s = Series::new("", (20, 20, 20), pts)
                        .csv(
                            format!("contour;theta_s={}", csv::num(level, 6)),
                            Some(q_ths()),
                        )
                        .direct(super::model::tick_text(level, dec))
                        .digits(Digits::Interpolated, Digits::Interpolated);
                    s.width = 0.6;
                    p.series.push(s);
                }
            }
        }
    }
    let mut f = Figure::new(
        "plane_map",
        "The separation angle over the parameter plane",
        vec![p],
        1,
    )
    .heights(250.0, 200.0);
    f.colorbar = Some(ColorBar {
        label: "θₛ (rad)".into(),
        range: (lo, hi),
        marks: Vec::new(),
        steps: Vec::new(),
    });
    f.extra_csv.push(
        csv::write(&records)
            .lines()
            .skip(1)
            .map(|l| format!("{l}\n"))
            .collect(),
    );
    Some(f.caption(format!(
        "θₛ in radians (colour) at each of the {} × {} computed nodes over m₂/m₁ from {} to {} (log scale) and k₂ from {} to {}: every cell is one oracle value, drawn as it is (no smoothing; hover for the value). Contours every {} rad ({}°), labelled, are interpolated between the nodes. θₛ ranges from {} ({}°) to {} ({}°). {PLANE_TEXT}",
        hr.len(),
        hk.len(),
        hr[0],
        hr[hr.len() - 1],
        hk[0],
        hk[hk.len() - 1],
        super::model::tick_text(step, dec),
        fmt(step.to_degrees(), 1),
        fmt(lo, 4),
        fmt(lo.to_degrees(), 1),
        fmt(hi, 4),
        fmt(hi.to_degrees(), 1),
    )))
}
