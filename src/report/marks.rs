//! The marks cylroll draws itself on a figure and its legend: texts of
//! its own (with a halo inside a plot), markers, and the colours and
//! widths in canvas units.

use super::canvas::{hex, n, xml, Canvas, Doc, Rgb, S};
use super::model::Shape;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::cell::RefCell;
use std::fmt::Write as _;
use std::rc::Rc;

/// A plotters colour.
pub(super) fn rgb(c: Rgb) -> RGBColor {
    RGBColor(c.0, c.1, c.2)
}

/// Points to canvas units.
pub(super) fn width(w: f64) -> u32 {
    (w * S).round() as u32
}

/// A darker shade for text in a curve's colour (contrast on white).
pub fn darker(c: Rgb) -> Rgb {
    let d = |v: u8| (f64::from(v) * 0.72) as u8;
    (d(c.0), d(c.1), d(c.2))
}

/// A text of cylroll's own (class `t`), with a white halo inside a plot.
pub fn own_text(
    doc: &Rc<RefCell<Doc>>,
    (x, y): (f64, f64),
    t: &str,
    size: f64,
    anchor: &str,
    color: Rgb,
    halo: bool,
) {
    let halo = if halo {
        " stroke=\"#ffffff\" stroke-width=\"1.8\" stroke-linejoin=\"round\" paint-order=\"stroke\""
    } else {
        ""
    };
    let mut d = doc.borrow_mut();
    let _ = writeln!(
        d.body,
        "<text class=\"t\" x=\"{}\" y=\"{}\" font-size=\"{}\" text-anchor=\"{anchor}\" fill=\"{}\"{halo}>{}</text>",
        n(x),
        n(y),
        n(size),
        hex(color),
        xml(t)
    );
}

/// A marker at `c` (pt) drawn with plotters' elements on the root area.
#[allow(clippy::too_many_arguments)]
pub fn draw_marker(
    root: &DrawingArea<Canvas, Shift>,
    doc: &Rc<RefCell<Doc>>,
    class: &'static str,
    c: (f64, f64),
    shape: Shape,
    r: f64,
    color: Rgb,
    filled: bool,
    title: &str,
) {
    doc.borrow_mut().set(class, "", title);
    let at = ((c.0 * S).round() as i32, (c.1 * S).round() as i32);
    let u = |v: f64| (v * S).round() as i32;
    let (fill, stroke) = if filled {
        (rgb(color).filled(), BLACK.stroke_width(width(0.4)))
    } else {
        (WHITE.filled(), rgb(color).stroke_width(width(0.9)))
    };
    let outline: Vec<(f64, f64)> = match shape {
        Shape::Square => {
            let a = r * 0.86;
            vec![(-a, -a), (a, -a), (a, a), (-a, a)]
        }
        Shape::Triangle | Shape::TriangleDown => {
            let s = if shape == Shape::Triangle { 1.0 } else { -1.0 };
            let a = r * 1.15;
            vec![
                (0.0, -s * a),
                (a * 0.866, s * a * 0.5),
                (-a * 0.866, s * a * 0.5),
            ]
        }
        Shape::Diamond => {
            let a = r * 1.2;
            vec![(0.0, -a), (a, 0.0), (0.0, a), (-a, 0.0)]
        }
        _ => Vec::new(),
    };
    let _ = match shape {
        Shape::Circle => root.draw(
            &(EmptyElement::at(at)
                + Circle::new((0, 0), width(r), fill)
                + Circle::new((0, 0), width(r), stroke)),
        ),
        Shape::Cross => {
            let a = u(r * 0.85);
            let st = rgb(color).stroke_width(width(1.0));
            root.draw(
                &(EmptyElement::at(at)
                    + PathElement::new(vec![(-a, -a), (a, a)], st)
                    + PathElement::new(vec![(-a, a), (a, -a)], st)),
            )
        }
        _ => {
            let pts: Vec<(i32, i32)> = outline.iter().map(|&(a, b)| (u(a), u(b))).collect();
            let mut closed = pts.clone();
            closed.push(pts[0]);
            root.draw(
                &(EmptyElement::at(at)
                    + Polygon::new(pts, fill)
                    + PathElement::new(closed, stroke)),
            )
        }
    };
}
