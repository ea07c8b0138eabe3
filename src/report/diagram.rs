//! The sign-convention diagram: the two cylinders, the angles θ, φ₁, φ₂ and
//! the four contact forces F₁, N₁, F₂₁, N₁₂ drawn in their positive
//! directions (the conventions of the project README, "Conventions", and of
//! `mechanics`: x right, y up, θ clockwise from the vertical, φ₁ clockwise,
//! φ₂ − θ counter-clockwise, F₂₁ along (cos θ, −sin θ) on cylinder 2).

use super::canvas::{xml, FONT};
use super::model::{Figure, PALETTE};
use std::fmt::Write as _;

/// Size of the drawing in its own units (the viewBox).
pub const SIZE: (u32, u32) = (560, 640);

/// Its width at print size: one journal column, 85 mm, in pt (every text
/// is at least 17 units, 7.3 pt there).
pub const PRINT_W: f64 = 85.0 / 25.4 * 72.0;

fn hex(c: (u8, u8, u8)) -> String {
    format!("#{:02x}{:02x}{:02x}", c.0, c.1, c.2)
}

struct D {
    s: String,
}

impl D {
    fn text(&mut self, x: f64, y: f64, t: &str, color: &str, anchor: &str, size: f64) {
        let _ = writeln!(
            self.s,
            "<text x=\"{x:.1}\" y=\"{y:.1}\" font-size=\"{size}\" text-anchor=\"{anchor}\" fill=\"{color}\" stroke=\"#ffffff\" stroke-width=\"4\" stroke-linejoin=\"round\" paint-order=\"stroke\">{}</text>",
            xml(t)
        );
    }
    fn arrow(
        &mut self,
        a: (f64, f64),
        b: (f64, f64),
        color: &str,
        id: &str,
        title: &str,
        width: f64,
    ) {
        let _ = writeln!(
            self.s,
            "<path d=\"M{:.1} {:.1}L{:.1} {:.1}\" stroke=\"{color}\" stroke-width=\"{width}\" fill=\"none\" marker-end=\"url(#{id})\"><title>{}</title></path>",
            a.0,
            a.1,
            b.0,
            b.1,
            xml(title)
        );
    }
    /// A circular arc around `c` of radius `r` from angle `a0` to `a1`
    /// (degrees, clockwise from the upward vertical), with an arrow head at
    /// its end.
    #[allow(clippy::too_many_arguments)]
    fn arc(&mut self, c: (f64, f64), r: f64, a0: f64, a1: f64, color: &str, id: &str, title: &str) {
        let p = |a: f64| {
            let t = a.to_radians();
            (c.0 + r * t.sin(), c.1 - r * t.cos())
        };
        let (s, e) = (p(a0), p(a1));
        let large = u8::from((a1 - a0).abs() > 180.0);
        let sweep = u8::from(a1 > a0);
        let _ = writeln!(
            self.s,
            "<path d=\"M{:.1} {:.1}A{r:.1} {r:.1} 0 {large} {sweep} {:.1} {:.1}\" stroke=\"{color}\" stroke-width=\"2\" fill=\"none\" marker-end=\"url(#{id})\"><title>{}</title></path>",
            s.0,
            s.1,
            e.0,
            e.1,
            xml(title)
        );
    }
}

/// The diagram as SVG text.
pub fn svg() -> String {
    let (w, h) = (f64::from(SIZE.0), f64::from(SIZE.1));
    let mut d = D { s: String::new() };
    let _ = writeln!(
        d.s,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}pt\" height=\"{}pt\" viewBox=\"0 0 {w} {h}\" font-family=\"{FONT}\" font-size=\"17\">",
        super::canvas::n(PRINT_W),
        super::canvas::n(PRINT_W * h / w)
    );
    d.s.push_str("<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n");
    arrow_heads(&mut d);
    let floor_y = 420.0;
    let r = 105.0;
    let th = 32f64.to_radians();
    let c1 = (210.0, floor_y - r);
    let c2 = (c1.0 + 2.0 * r * th.sin(), c1.1 - 2.0 * r * th.cos());
    let p = (c1.0 + r * th.sin(), c1.1 - r * th.cos());
    floor(&mut d, floor_y, w);
    cylinders(&mut d, c1, c2, r);
    angles(&mut d, c1, c2, r);
    forces(&mut d, (c1.0, floor_y), p, th);
    // axes
    let o = (40.0, 60.0);
    d.arrow(o, (o.0 + 50.0, o.1), "#000", "ak", "x", 1.5);
    d.arrow(o, (o.0, o.1 - 45.0), "#000", "ak", "y", 1.5);
    d.text(o.0 + 56.0, o.1 + 5.0, "x", "#000", "start", 17.0);
    d.text(o.0, o.1 - 50.0, "y", "#000", "middle", 17.0);
    key(&mut d);
    d.s.push_str("</svg>\n");
    d.s
}

/// The arrow heads, one per colour.
fn arrow_heads(d: &mut D) {
    d.s.push_str("<defs>");
    let colors = [
        ("ak", (0, 0, 0)),
        ("a0", PALETTE[0]),
        ("a1", PALETTE[1]),
        ("a2", PALETTE[2]),
        ("a3", PALETTE[3]),
        ("a4", (110, 110, 110)),
    ];
    for (id, c) in colors {
        let _ = write!(
            d.s,
            "<marker id=\"{id}\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"7\" markerHeight=\"7\" orient=\"auto-start-reverse\"><path d=\"M0 0L10 5L0 10z\" fill=\"{}\"/></marker>",
            hex(c)
        );
    }
    d.s.push_str("</defs>\n");
}

/// The floor, hatched.
fn floor(d: &mut D, floor_y: f64, w: f64) {
    let _ = writeln!(
        d.s,
        "<path d=\"M30 {floor_y}H{}\" stroke=\"#000\" stroke-width=\"2\"/>",
        w - 30.0
    );
    let mut hatch = String::new();
    let mut x = 40.0;
    while x < w - 30.0 {
        let _ = write!(hatch, "M{x:.0} {floor_y}l-10 12");
        x += 18.0;
    }
    let _ = writeln!(
        d.s,
        "<path d=\"{hatch}\" stroke=\"#999\" stroke-width=\"1\"/>"
    );
}

/// The two cylinders with their centres and numbers.
fn cylinders(d: &mut D, c1: (f64, f64), c2: (f64, f64), r: f64) {
    for (c, name) in [
        (c1, "cylinder 1 (m₁, r₁, k₁)"),
        (c2, "cylinder 2 (m₂, r₂, k₂)"),
    ] {
        let _ = writeln!(
            d.s,
            "<circle cx=\"{:.1}\" cy=\"{:.1}\" r=\"{r}\" fill=\"#f4f4f4\" stroke=\"#000\" stroke-width=\"2\"><title>{}</title></circle><circle cx=\"{:.1}\" cy=\"{:.1}\" r=\"3\" fill=\"#000\"/>",
            c.0,
            c.1,
            xml(name),
            c.0,
            c.1
        );
    }
    d.text(c1.0 - r - 8.0, c1.1 + 70.0, "1", "#000", "end", 19.0);
    d.text(c2.0 + r * 0.8, c2.1 - r * 0.8, "2", "#000", "start", 19.0);
}

/// θ, φ1 and φ2 − θ as arcs with their names.
fn angles(d: &mut D, c1: (f64, f64), c2: (f64, f64), r: f64) {
    let grey = "#6e6e6e";
    // θ: vertical through C1 and the line of centres
    let _ = writeln!(
        d.s,
        "<path d=\"M{:.1} {:.1}V{:.1}\" stroke=\"{grey}\" stroke-width=\"1.2\" stroke-dasharray=\"5 4\"/><path d=\"M{:.1} {:.1}L{:.1} {:.1}\" stroke=\"{grey}\" stroke-width=\"1.2\" stroke-dasharray=\"5 4\"/>",
        c1.0,
        c1.1,
        c1.1 - 2.0 * r - 20.0,
        c1.0,
        c1.1,
        c2.0,
        c2.1
    );
    let arcs = [
        (
            c1,
            48.0,
            (0.0, 32.0),
            "θ: the line of centres, clockwise from the vertical",
            ("θ", (20.0, -56.0), 19.0),
        ),
        (
            c1,
            62.0,
            (200.0, 290.0),
            "φ₁: clockwise rotation of cylinder 1",
            ("φ₁", (-36.0, 12.0), 18.0),
        ),
        (
            c2,
            62.0,
            (120.0, 30.0),
            "φ₂ − θ: counter-clockwise rotation of cylinder 2",
            ("φ₂ − θ", (10.0, 30.0), 17.0),
        ),
    ];
    for (c, radius, (a0, a1), title, (name, off, size)) in arcs {
        d.arc(c, radius, a0, a1, "#000", "ak", title);
        d.text(c.0 + off.0, c.1 + off.1, name, "#000", "middle", size);
    }
}

/// The four forces in their positive directions: on cylinder 1 at the floor
/// point `fp`, on cylinder 2 at the contact point `p`.
fn forces(d: &mut D, fp: (f64, f64), p: (f64, f64), th: f64) {
    let len = 75.0;
    let n = (th.sin(), -th.cos());
    let t = (th.cos(), th.sin());
    // (from, direction, colour, title, name, name offset from the tip, anchor)
    let arrows = [
        (
            fp,
            (1.0, 0.0),
            0,
            "F₁ > 0: the floor pushes cylinder 1 to +x",
            "F₁",
            (6.0, -6.0),
            "start",
        ),
        (
            fp,
            (0.0, -1.0),
            1,
            "N₁ > 0: the floor pushes cylinder 1 up",
            "N₁",
            (-8.0, 4.0),
            "end",
        ),
        (
            p,
            t,
            2,
            "F₂₁ > 0: cylinder 1's tangential force on cylinder 2 along (cos θ, −sin θ)",
            "F₂₁",
            (6.0, 16.0),
            "start",
        ),
        (
            p,
            n,
            3,
            "N₁₂ > 0: cylinder 1 pushes cylinder 2 away along the line of centres",
            "N₁₂",
            (-8.0, -4.0),
            "end",
        ),
    ];
    for (from, dir, i, title, name, off, anchor) in arrows {
        let tip = (from.0 + len * dir.0, from.1 + len * dir.1);
        let color = hex(PALETTE[i]);
        d.arrow(from, tip, &color, &format!("a{i}"), title, 3.0);
        d.text(tip.0 + off.0, tip.1 + off.1, name, &color, anchor, 19.0);
    }
    let _ = writeln!(
        d.s,
        "<circle cx=\"{:.1}\" cy=\"{:.1}\" r=\"3.5\" fill=\"#000\"/>",
        p.0, p.1
    );
}

/// The key of positive directions.
fn key(d: &mut D) {
    let kx = 30.0;
    let lines = [
        "Positive directions:",
        "F₁, N₁: floor on cylinder 1 (x, y)",
        "N₁₂, F₂₁: cylinder 1 on cylinder 2,",
        "   normal and tangential",
        "(on cylinder 1: equal and opposite)",
        "θ: clockwise from the vertical",
        "φ₁: clockwise; φ₂ − θ: anticlockwise",
        "rolling: x₁ = r₁φ₁, r₂φ₂ = r₁(φ₁ − θ)",
    ];
    for (i, l) in lines.iter().enumerate() {
        let _ = writeln!(
            d.s,
            "<text x=\"{kx}\" y=\"{}\" font-size=\"17\" fill=\"#000\"{}>{}</text>",
            466.0 + 21.0 * i as f64,
            if i == 0 { " font-weight=\"bold\"" } else { "" },
            xml(l)
        );
    }
}

/// The diagram as a figure of the report (one column, 85 mm, in both
/// layouts).
pub fn figure() -> Figure {
    let mut f = Figure::new(
        "conventions",
        "Sign conventions: angles and forces in their positive directions",
        Vec::new(),
        1,
    );
    let svg = svg();
    f.raw = Some((svg.clone(), svg));
    f.caption = "The two cylinders with θ, φ₁, φ₂ and the four contact forces drawn in their positive directions (x right, y up). \
                 θ is the line of centres measured clockwise from the vertical; φ₁ is cylinder 1's clockwise rotation; φ₂ is the \
                 paper's angle (eq. 2), so φ₂ − θ is cylinder 2's counter-clockwise rotation. F₁ and N₁ are the floor's force on \
                 cylinder 1 (the holder's when cylinder 1 is held fixed); N₁₂ and F₂₁ are cylinder 1's force on cylinder 2, normal \
                 (along the line of centres, positive while they press) and tangential (along (cos θ, −sin θ)). A negative value in \
                 a plot points the other way."
        .into();
    f
}
