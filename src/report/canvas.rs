//! The drawing surface: cylroll's own [`DrawingBackend`] for plotters, which
//! writes SVG in print units (1 unit = 1 pt) with sub-point coordinates, and
//! the font everything is measured and embedded with.
//!
//! plotters hands a backend whole-number coordinates. The canvas therefore
//! reports a size [`S`] times larger than the figure and divides every
//! coordinate by `S` when it writes it: the SVG keeps its viewBox in points
//! and every coordinate 1/100 pt. The backend also carries what plotters has
//! no element for, set by the caller before plotters draws: the class of
//! what is drawn (curves, markers, reference lines, frames: what the
//! browser's overlap test reads), a dash pattern written as
//! `stroke-dasharray` (a vector dash, not many small segments) and a hover
//! `<title>`.

use plotters_backend::{
    text_anchor::{HPos, VPos},
    BackendColor, BackendCoord, BackendStyle, BackendTextStyle, DrawingBackend, DrawingErrorKind,
    FontTransform,
};
use std::cell::RefCell;
use std::fmt::Write as _;
use std::rc::Rc;
use std::sync::OnceLock;

/// Backend units per point.
pub const S: f64 = 100.0;

/// The figures' font: DejaVu Sans, embedded (its licence beside it in
/// `src/report/font/`), so that text is measured here exactly as the PDF
/// embeds it and as a browser with DejaVu Sans draws it.
pub const FONT_BYTES: &[u8] = include_bytes!("font/DejaVuSans.ttf");

/// The font family written into the SVG.
pub const FONT: &str = "DejaVu Sans, Verdana, sans-serif";

/// A colour as 8-bit RGB.
pub type Rgb = (u8, u8, u8);

struct Metrics {
    face: ttf_parser::Face<'static>,
    upem: f64,
}

fn metrics() -> &'static Metrics {
    static M: OnceLock<Metrics> = OnceLock::new();
    M.get_or_init(|| {
        let face = ttf_parser::Face::parse(FONT_BYTES, 0).expect("the embedded font parses");
        let upem = f64::from(face.units_per_em());
        Metrics { face, upem }
    })
}

/// The font's ascent in em (the top of a text's box above its baseline).
pub fn ascent() -> f64 {
    let m = metrics();
    f64::from(m.face.ascender()) / m.upem
}

/// The font's descent in em (the bottom of a text's box below its baseline).
pub fn descent() -> f64 {
    let m = metrics();
    -f64::from(m.face.descender()) / m.upem
}

/// The advance width of `s` at `size` pt, in pt.
pub fn text_width(s: &str, size: f64) -> f64 {
    let m = metrics();
    let units: f64 = s
        .chars()
        .map(|c| {
            m.face
                .glyph_index(c)
                .and_then(|g| m.face.glyph_hor_advance(g))
                .map_or(0.6 * m.upem, f64::from)
        })
        .sum();
    units / m.upem * size
}

/// A number for the SVG: at most two decimals, no "-0".
pub fn n(v: f64) -> String {
    let s = format!("{v:.2}");
    let s = s.trim_end_matches('0').trim_end_matches('.').to_string();
    if s == "-0" {
        "0".into()
    } else {
        s
    }
}

/// `#rrggbb`.
pub fn hex(c: Rgb) -> String {
    format!("#{:02x}{:02x}{:02x}", c.0, c.1, c.2)
}

/// XML escape.
pub fn xml(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// What the next elements drawn by plotters are: their class, dash
/// pattern (pt, in print units) and hover text.
#[derive(Debug, Clone, Default)]
pub struct Ctx {
    /// The SVG class (`c` curve, `m` marker, `r` reference line, `frame`,
    /// `grid`, `axis`, `band`; empty: none).
    pub class: &'static str,
    /// `stroke-dasharray` in pt (empty: solid).
    pub dash: String,
    /// Hover text (empty: none).
    pub title: String,
    /// Fill opacity of filled shapes (1: opaque).
    pub opacity: f64,
}

/// The SVG being written: plotters' elements and cylroll's own, in drawing
/// order.
#[derive(Debug, Default)]
pub struct Doc {
    /// The elements.
    pub body: String,
    /// What plotters draws next.
    pub ctx: Ctx,
    /// Labels left out for want of a free place.
    pub dropped: Vec<String>,
}

impl Doc {
    /// Sets the class, dash and hover text of what plotters draws next.
    pub fn set(&mut self, class: &'static str, dash: &str, title: &str) {
        self.ctx = Ctx {
            class,
            dash: dash.to_string(),
            title: title.to_string(),
            opacity: 1.0,
        };
    }

    fn attrs(&self) -> String {
        let mut a = String::new();
        if !self.ctx.class.is_empty() {
            let _ = write!(a, " class=\"{}\"", self.ctx.class);
        }
        a
    }

    fn title(&self) -> String {
        if self.ctx.title.is_empty() {
            String::new()
        } else {
            format!("<title>{}</title>", xml(&self.ctx.title))
        }
    }

    fn close(&mut self, tag: &str) {
        let t = self.title();
        if t.is_empty() {
            self.body.push_str("/>\n");
        } else {
            let _ = writeln!(self.body, ">{t}</{tag}>");
        }
    }

    fn stroke(&self, c: BackendColor, width: u32) -> String {
        let dash = if self.ctx.dash.is_empty() {
            String::new()
        } else {
            format!(" stroke-dasharray=\"{}\"", self.ctx.dash)
        };
        let op = if c.alpha < 1.0 {
            format!(" stroke-opacity=\"{}\"", n(c.alpha))
        } else {
            String::new()
        };
        format!(
            " fill=\"none\" stroke=\"{}\" stroke-width=\"{}\" stroke-linejoin=\"round\" stroke-linecap=\"butt\"{dash}{op}",
            hex(c.rgb),
            n(f64::from(width) / S)
        )
    }

    fn fill(&self, c: BackendColor) -> String {
        let a = c.alpha * self.ctx.opacity;
        let op = if a < 1.0 {
            format!(" fill-opacity=\"{}\"", n(a))
        } else {
            String::new()
        };
        // the cells of a map are outlined in their own colour, so that no
        // seam of the background shows between neighbours where a renderer
        // anti-aliases their shared edges
        let stroke = if self.ctx.class == "patch" && a >= 1.0 {
            format!(
                " stroke=\"{}\" stroke-width=\"0.35\" stroke-linejoin=\"round\"",
                hex(c.rgb)
            )
        } else {
            " stroke=\"none\"".to_string()
        };
        format!(" fill=\"{}\"{stroke}{op}", hex(c.rgb))
    }

    /// A path through pixel points (already in pt).
    pub fn path_d(pts: &[(f64, f64)]) -> String {
        let mut d = String::new();
        for (i, p) in pts.iter().enumerate() {
            let _ = write!(d, "{}{} {}", if i == 0 { "M" } else { "L" }, n(p.0), n(p.1));
        }
        d
    }
}

fn pt(c: BackendCoord) -> (f64, f64) {
    (f64::from(c.0) / S, f64::from(c.1) / S)
}

/// The error of the canvas (it never fails).
#[derive(Debug)]
pub struct Never;

impl std::fmt::Display for Never {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("never")
    }
}

impl std::error::Error for Never {}

/// plotters' backend on a [`Doc`]: `w` × `h` pt, reported to plotters
/// [`S`] times larger.
pub struct Canvas {
    doc: Rc<RefCell<Doc>>,
    size: (u32, u32),
}

impl Canvas {
    /// A canvas of `w` × `h` pt writing into `doc`.
    pub fn new(doc: Rc<RefCell<Doc>>, w: f64, h: f64) -> Self {
        Canvas {
            doc,
            size: ((w * S).round() as u32, (h * S).round() as u32),
        }
    }
}

type R = Result<(), DrawingErrorKind<Never>>;

impl DrawingBackend for Canvas {
    type ErrorType = Never;

    fn get_size(&self) -> (u32, u32) {
        self.size
    }

    fn ensure_prepared(&mut self) -> R {
        Ok(())
    }

    fn present(&mut self) -> R {
        Ok(())
    }

    fn draw_pixel(&mut self, p: BackendCoord, c: BackendColor) -> R {
        let mut d = self.doc.borrow_mut();
        let (x, y) = pt(p);
        let f = d.fill(c);
        let _ = write!(
            d.body,
            "<rect x=\"{}\" y=\"{}\" width=\"0.01\" height=\"0.01\"{f}",
            n(x),
            n(y)
        );
        d.close("rect");
        Ok(())
    }

    fn draw_line<St: BackendStyle>(&mut self, a: BackendCoord, b: BackendCoord, s: &St) -> R {
        self.draw_path([a, b], s)
    }

    fn draw_rect<St: BackendStyle>(
        &mut self,
        ul: BackendCoord,
        br: BackendCoord,
        s: &St,
        fill: bool,
    ) -> R {
        let mut d = self.doc.borrow_mut();
        let ((x0, y0), (x1, y1)) = (pt(ul), pt(br));
        let paint = if fill {
            d.fill(s.color())
        } else {
            d.stroke(s.color(), s.stroke_width())
        };
        let a = d.attrs();
        let _ = write!(
            d.body,
            "<rect{a} x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"{paint}",
            n(x0.min(x1)),
            n(y0.min(y1)),
            n((x1 - x0).abs()),
            n((y1 - y0).abs())
        );
        d.close("rect");
        Ok(())
    }

    fn draw_path<St: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        path: I,
        s: &St,
    ) -> R {
        let pts: Vec<(f64, f64)> = path.into_iter().map(pt).collect();
        if pts.len() < 2 || s.color().alpha == 0.0 {
            return Ok(());
        }
        let mut d = self.doc.borrow_mut();
        let (a, st) = (d.attrs(), d.stroke(s.color(), s.stroke_width()));
        let _ = write!(d.body, "<path{a} d=\"{}\"{st}", Doc::path_d(&pts));
        d.close("path");
        Ok(())
    }

    fn draw_circle<St: BackendStyle>(&mut self, c: BackendCoord, r: u32, s: &St, fill: bool) -> R {
        let mut d = self.doc.borrow_mut();
        let (x, y) = pt(c);
        let paint = if fill {
            d.fill(s.color())
        } else {
            d.stroke(s.color(), s.stroke_width())
        };
        let a = d.attrs();
        let _ = write!(
            d.body,
            "<circle{a} cx=\"{}\" cy=\"{}\" r=\"{}\"{paint}",
            n(x),
            n(y),
            n(f64::from(r) / S)
        );
        d.close("circle");
        Ok(())
    }

    fn fill_polygon<St: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        vert: I,
        s: &St,
    ) -> R {
        let pts: Vec<(f64, f64)> = vert.into_iter().map(pt).collect();
        if pts.len() < 3 {
            return Ok(());
        }
        let mut d = self.doc.borrow_mut();
        let (a, f) = (d.attrs(), d.fill(s.color()));
        let _ = write!(d.body, "<path{a} d=\"{}Z\"{f}", Doc::path_d(&pts));
        d.close("path");
        Ok(())
    }

    fn draw_text<T: BackendTextStyle>(&mut self, text: &str, style: &T, pos: BackendCoord) -> R {
        let size = style.size() / S;
        let anchor = style.anchor();
        let (x, y) = pt(pos);
        // the baseline from the anchor's vertical position (the text's box
        // is the font's ascent and descent, as a browser measures it)
        let (asc, desc) = (ascent() * size, descent() * size);
        let dy = match anchor.v_pos {
            VPos::Top => asc,
            VPos::Center => (asc - desc) / 2.0,
            VPos::Bottom => -desc,
        };
        let ta = match anchor.h_pos {
            HPos::Left => "start",
            HPos::Center => "middle",
            HPos::Right => "end",
        };
        let mut d = self.doc.borrow_mut();
        let (tx, ty, rot) = match style.transform() {
            FontTransform::Rotate270 => (
                x + dy,
                y,
                format!(" transform=\"rotate(-90 {} {})\"", n(x + dy), n(y)),
            ),
            FontTransform::Rotate90 => (
                x - dy,
                y,
                format!(" transform=\"rotate(90 {} {})\"", n(x - dy), n(y)),
            ),
            _ => (x, y + dy, String::new()),
        };
        let c = style.color();
        let _ = writeln!(
            d.body,
            "<text class=\"t\" x=\"{}\" y=\"{}\" font-size=\"{}\" text-anchor=\"{ta}\" fill=\"{}\"{rot}>{}</text>",
            n(tx),
            n(ty),
            n(size),
            hex(c.rgb),
            xml(text)
        );
        Ok(())
    }

    fn estimate_text_size<T: BackendTextStyle>(
        &self,
        text: &str,
        style: &T,
    ) -> Result<(u32, u32), DrawingErrorKind<Never>> {
        let size = style.size() / S;
        let w = text_width(text, size);
        let h = (ascent() + descent()) * size;
        Ok(((w * S).ceil() as u32, (h * S).ceil() as u32))
    }
}

/// The SVG document around `body`: `w` × `h` pt (its print size: the
/// width and height carry the unit), the viewBox in pt.
pub fn svg_document(w: f64, h: f64, body: &str) -> String {
    format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}pt\" height=\"{h}pt\" viewBox=\"0 0 {w} {h}\" font-family=\"{FONT}\" style=\"font-kerning:none\">\n\
         <rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n{body}</svg>\n",
        w = n(w),
        h = n(h),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_font_measures_text() {
        let w = text_width("θₛ = 1.047", 7.0);
        assert!(w > 20.0 && w < 45.0, "{w}");
        assert!((ascent() + descent() - 1.164).abs() < 0.01);
        assert_eq!(n(-0.001), "0");
        assert_eq!(n(2.5), "2.5");
    }
}
