//! The figure model: a [`Figure`] is [`Panel`]s of [`Series`] (with their
//! markers, reference lines, shaded bands and cells), a legend and a colour
//! bar, described once and rendered in both layouts, as PDF and as CSV.
//!
//! The one place of the crate where `f64` is used for numbers: the plotted
//! points are oracle values (verified to the digits the report asks for)
//! rounded to `f64` for drawing. A `NaN` point breaks a curve (a phase
//! boundary).

pub use super::canvas::Rgb;

/// Colours of the Okabe–Ito palette (distinguishable with colour-blindness).
pub const PALETTE: [Rgb; 8] = [
    (0, 114, 178),   // blue
    (213, 94, 0),    // vermillion
    (0, 158, 115),   // bluish green
    (204, 121, 167), // reddish purple
    (230, 159, 0),   // orange
    (86, 180, 233),  // sky blue
    (0, 0, 0),       // black
    (120, 120, 120), // grey
];

/// Grey of reference lines (separation, the branch point).
pub const REF: Rgb = (80, 80, 80);

/// How a line is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dash {
    /// Solid.
    Solid,
    /// Dashed.
    Dashed,
    /// Dotted.
    Dotted,
    /// Dash-dot.
    DashDot,
}

impl Dash {
    /// `stroke-dasharray` in pt (empty: solid).
    pub fn array(self) -> &'static str {
        match self {
            Dash::Solid => "",
            Dash::Dashed => "4 2",
            Dash::Dotted => "1 1.6",
            Dash::DashDot => "4.5 1.6 1 1.6",
        }
    }
}

/// A marker shape: every curve of a panel gets its own, legible in
/// greyscale and for colour-blind readers.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shape {
    /// ○
    Circle,
    /// □
    Square,
    /// △
    Triangle,
    /// ◇
    Diamond,
    /// ▽
    TriangleDown,
    /// ×
    Cross,
}

/// The shapes in the order curves get them.
pub const SHAPES: [Shape; 6] = [
    Shape::Circle,
    Shape::Square,
    Shape::Triangle,
    Shape::Diamond,
    Shape::TriangleDown,
    Shape::Cross,
];

/// The digits a CSV value carries.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Digits {
    /// Verified to this many significant digits.
    Verified(u32),
    /// An exact input (a time or angle asked for).
    Exact,
    /// Computed in double precision from a closed form (15 digits).
    Double,
    /// Interpolated between verified values (a contour): not verified.
    Interpolated,
}

impl Digits {
    /// The `digits` column.
    pub fn text(self) -> String {
        match self {
            Digits::Verified(d) => d.to_string(),
            Digits::Exact => "exact".into(),
            Digits::Double => "15".into(),
            Digits::Interpolated => "interpolated".into(),
        }
    }

    /// Significant digits to print a value with.
    pub fn sig(self) -> usize {
        match self {
            Digits::Verified(d) => d as usize,
            Digits::Exact => 15,
            Digits::Double => 15,
            Digits::Interpolated => 6,
        }
    }
}

/// A quantity of an axis or a curve: its ASCII name and unit for the CSV
/// and its label on the figure.
#[derive(Debug, Clone, PartialEq)]
pub struct Quantity {
    /// ASCII name (`t`, `theta`, `N12`).
    pub name: String,
    /// ASCII unit (`tau`, `rad`, `m1*g`, `1`).
    pub unit: String,
    /// Axis label as printed, e.g. `θ (rad)`.
    pub label: String,
}

impl Quantity {
    /// A quantity.
    pub fn new(name: &str, unit: &str, label: &str) -> Self {
        Quantity {
            name: name.into(),
            unit: unit.into(),
            label: label.into(),
        }
    }
}

/// Legend order: every figure lists its entries in this order of kinds.
pub mod order {
    /// Curves, in the order they were added.
    pub const CURVE: u32 = 0;
    /// A curve's markers (slip onsets, maxima).
    pub const MARK: u32 = 100;
    /// The branch point θ*.
    pub const BRANCH: u32 = 200;
    /// Separation.
    pub const SEPARATION: u32 = 210;
    /// The first impact.
    pub const IMPACT: u32 = 220;
    /// Closed forms and limits.
    pub const LIMIT: u32 = 300;
    /// Shaded phases and windows.
    pub const SHADE: u32 = 400;
}

/// One curve.
#[derive(Debug, Clone)]
pub struct Series {
    /// Legend text (empty: not in the legend).
    pub label: String,
    /// The curve in the CSV (ASCII, e.g. `model=roll/roll`).
    pub key: String,
    /// The y quantity (None: the panel's).
    pub yq: Option<Quantity>,
    /// Colour.
    pub color: Rgb,
    /// Line style.
    pub dash: Dash,
    /// Line width in pt.
    pub width: f64,
    /// Points in data coordinates; a NaN point breaks the line.
    pub points: Vec<(f64, f64)>,
    /// The phase of each point (empty: none), for the CSV.
    pub phases: Vec<String>,
    /// Digits of x and of y.
    pub digits: (Digits, Digits),
    /// Marker shape (legend, periodic and end markers).
    pub shape: Option<Shape>,
    /// A marker every `every` points (0: none), from point `phase`.
    pub every: usize,
    /// Offset of the periodic markers.
    pub offset: usize,
    /// Hover text of a hollow marker at the last point (None: none).
    pub end: Option<String>,
    /// A label written beside the curve's end where it is free.
    pub direct: Option<String>,
    /// Drawn (false: in the CSV only).
    pub drawn: bool,
}

impl Series {
    /// A solid curve of width 1 pt.
    pub fn new(label: impl Into<String>, color: Rgb, points: Vec<(f64, f64)>) -> Self {
        let label = label.into();
        Series {
            key: ascii_key(&label),
            label,
            yq: None,
            color,
            dash: Dash::Solid,
            width: 1.0,
            points,
            phases: Vec::new(),
            digits: (Digits::Exact, Digits::Double),
            shape: None,
            every: 0,
            offset: 0,
            end: None,
            direct: None,
            drawn: true,
        }
    }

    /// With a line style.
    pub fn dashed(mut self, dash: Dash) -> Self {
        self.dash = dash;
        self
    }

    /// With a marker shape.
    pub fn shape(mut self, s: Shape) -> Self {
        self.shape = Some(s);
        self
    }

    /// With a hollow end marker and its hover text.
    pub fn end_marker(mut self, title: impl Into<String>) -> Self {
        self.end = Some(title.into());
        self
    }

    /// With periodic markers.
    pub fn every(mut self, every: usize, offset: usize) -> Self {
        self.every = every;
        self.offset = offset;
        self
    }

    /// With a direct label.
    pub fn direct(mut self, text: impl Into<String>) -> Self {
        self.direct = Some(text.into());
        self
    }

    /// With its CSV key and y quantity.
    pub fn csv(mut self, key: impl Into<String>, yq: Option<Quantity>) -> Self {
        self.key = key.into();
        self.yq = yq;
        self
    }

    /// With the digits of x and y.
    pub fn digits(mut self, x: Digits, y: Digits) -> Self {
        self.digits = (x, y);
        self
    }

    /// With the phase of every point.
    pub fn phases(mut self, p: Vec<String>) -> Self {
        self.phases = p;
        self
    }
}

/// An ASCII key from a label: letters, digits and `=/.-_` kept, Greek
/// letters and subscripts spelled out.
pub fn ascii_key(s: &str) -> String {
    let mut out = String::new();
    for c in s.chars() {
        let r = match c {
            'θ' => "theta",
            'φ' => "phi",
            'μ' => "mu",
            'τ' => "tau",
            '₀' => "0",
            '₁' => "1",
            '₂' => "2",
            'ₛ' => "s",
            '−' => "-",
            '*' | '∗' => "*",
            ' ' => "_",
            c if c.is_ascii_alphanumeric() || "=/.-_+".contains(c) => {
                out.push(c);
                continue;
            }
            _ => "",
        };
        out.push_str(r);
    }
    let mut s = out.replace("__", "_");
    while s.ends_with('_') {
        s.pop();
    }
    s
}

/// A marked point (an event, a maximum).
#[derive(Debug, Clone)]
pub struct Marker {
    /// Position (data).
    pub at: (f64, f64),
    /// Colour.
    pub color: Rgb,
    /// Shape.
    pub shape: Shape,
    /// Filled (else hollow).
    pub filled: bool,
    /// Hover text.
    pub title: String,
    /// Text written beside it where free.
    pub label: Option<String>,
    /// Its CSV key (ASCII).
    pub key: String,
    /// Digits of its coordinates.
    pub digits: Digits,
}

impl Marker {
    /// A filled marker.
    pub fn new(shape: Shape, at: (f64, f64), color: Rgb, title: impl Into<String>) -> Self {
        Marker {
            at,
            color,
            shape,
            filled: true,
            title: title.into(),
            label: None,
            key: String::new(),
            digits: Digits::Double,
        }
    }

    /// With a label.
    pub fn label(mut self, l: impl Into<String>) -> Self {
        self.label = Some(l.into());
        self
    }

    /// With a CSV key.
    pub fn key(mut self, k: impl Into<String>) -> Self {
        self.key = k.into();
        self
    }

    /// Hollow.
    pub fn hollow(mut self) -> Self {
        self.filled = false;
        self
    }

    /// With the digits of its coordinates.
    pub fn digits(mut self, d: Digits) -> Self {
        self.digits = d;
        self
    }
}

/// A vertical or horizontal reference line across the plot area.
#[derive(Debug, Clone)]
pub struct RefLine {
    /// x (vertical) or y (horizontal), data.
    pub at: f64,
    /// Vertical (x = at).
    pub vertical: bool,
    /// Colour.
    pub color: Rgb,
    /// Style.
    pub dash: Dash,
    /// Label (empty: none): a vertical line's is written beside the line
    /// inside the plot where free; a horizontal line's in the margin right
    /// of the plot at the line's height (labels there are stacked apart, so
    /// none is ever left out).
    pub label: String,
    /// Hover text.
    pub title: String,
    /// Digits of its position.
    pub digits: Digits,
    /// Its CSV key (ASCII; empty: made from the hover text).
    pub key: String,
}

impl RefLine {
    /// A vertical line at `x`.
    pub fn vertical(x: f64, dash: Dash, label: impl Into<String>) -> Self {
        let label = label.into();
        RefLine {
            at: x,
            vertical: true,
            color: REF,
            dash,
            title: label.clone(),
            label,
            digits: Digits::Double,
            key: String::new(),
        }
    }

    /// A horizontal line at `y`.
    pub fn horizontal(y: f64, color: Rgb, dash: Dash, label: impl Into<String>) -> Self {
        let label = label.into();
        RefLine {
            at: y,
            vertical: false,
            color,
            dash,
            title: label.clone(),
            label,
            digits: Digits::Double,
            key: String::new(),
        }
    }
}

/// A shaded interval of x across the plot (a phase, a window).
#[derive(Debug, Clone)]
pub struct Band {
    /// From and to (data x).
    pub x: (f64, f64),
    /// Fill.
    pub color: Rgb,
    /// Hover text.
    pub title: String,
}

/// A filled polygon or rectangle in data coordinates (map cells, bands of
/// a filled contour plot).
#[derive(Debug, Clone)]
pub struct Patch {
    /// Outline in chart coordinates (log10 of the value on a logarithmic
    /// axis).
    pub outline: Vec<(f64, f64)>,
    /// Fill.
    pub color: Rgb,
    /// Hover text.
    pub title: String,
}

/// An entry of the legend.
#[derive(Debug, Clone, PartialEq)]
pub struct LegendEntry {
    /// Text.
    pub label: String,
    /// Colour.
    pub color: Rgb,
    /// A line sample in this style.
    pub dash: Option<Dash>,
    /// A marker sample.
    pub shape: Option<Shape>,
    /// The marker filled.
    pub filled: bool,
    /// A filled box sample (shading).
    pub swatch: bool,
    /// Place in the legend ([`order`]).
    pub order: u32,
}

impl LegendEntry {
    /// A line sample.
    pub fn line(label: impl Into<String>, color: Rgb, dash: Dash, order: u32) -> Self {
        LegendEntry {
            label: label.into(),
            color,
            dash: Some(dash),
            shape: None,
            filled: false,
            swatch: false,
            order,
        }
    }

    /// A marker sample.
    pub fn marker(
        label: impl Into<String>,
        color: Rgb,
        shape: Shape,
        filled: bool,
        order: u32,
    ) -> Self {
        LegendEntry {
            label: label.into(),
            color,
            dash: None,
            shape: Some(shape),
            filled,
            swatch: false,
            order,
        }
    }

    /// A shading sample.
    pub fn swatch(label: impl Into<String>, color: Rgb) -> Self {
        LegendEntry {
            label: label.into(),
            color,
            dash: None,
            shape: None,
            filled: true,
            swatch: true,
            order: order::SHADE,
        }
    }
}

/// One chart.
#[derive(Debug, Clone)]
pub struct Panel {
    /// Title over the chart (empty: none).
    pub title: String,
    /// x quantity.
    pub xq: Quantity,
    /// y quantity.
    pub yq: Quantity,
    /// Logarithmic x axis.
    pub xlog: bool,
    /// Logarithmic y axis.
    pub ylog: bool,
    /// Grid lines at the ticks (false for maps, whose cells fill the plot).
    pub grid: bool,
    /// The curves' names (their `direct` labels) written in the margin right
    /// of the plot at the height of each curve's end, instead of in the
    /// legend (for curves that all end at the right edge).
    pub names_right: bool,
    /// Fixed x range (None: the data's, padded).
    pub xrange: Option<(f64, f64)>,
    /// Fixed y range.
    pub yrange: Option<(f64, f64)>,
    /// Curves.
    pub series: Vec<Series>,
    /// Marked points.
    pub markers: Vec<Marker>,
    /// Reference lines.
    pub lines: Vec<RefLine>,
    /// Shaded intervals.
    pub bands: Vec<Band>,
    /// Filled patches (drawn first).
    pub patches: Vec<Patch>,
    /// Notes written inside the plot where free.
    pub notes: Vec<String>,
}

impl Panel {
    /// An empty panel.
    pub fn new(title: impl Into<String>, xq: Quantity, yq: Quantity) -> Self {
        Panel {
            title: title.into(),
            xq,
            yq,
            xlog: false,
            ylog: false,
            grid: true,
            names_right: false,
            xrange: None,
            yrange: None,
            series: Vec::new(),
            markers: Vec::new(),
            lines: Vec::new(),
            bands: Vec::new(),
            patches: Vec::new(),
            notes: Vec::new(),
        }
    }
}

/// A colour bar under a map.
#[derive(Debug, Clone)]
pub struct ColorBar {
    /// Label.
    pub label: String,
    /// Value range.
    pub range: (f64, f64),
    /// Levels marked across the bar, with their text.
    pub marks: Vec<(f64, String)>,
    /// Discrete bands: the level boundaries (empty: a smooth map).
    pub steps: Vec<f64>,
}

/// A figure: its panels, legend and colour bar; the title and caption are
/// the page's.
#[derive(Debug, Clone)]
pub struct Figure {
    /// File stem (`main_motion`): `figures/STEM.svg`, `.narrow.svg`, `.pdf`,
    /// `.narrow.pdf`, `.csv`.
    pub stem: String,
    /// Title (the page's heading).
    pub title: String,
    /// Caption (the page's).
    pub caption: String,
    /// Panels, row by row.
    pub panels: Vec<Panel>,
    /// Columns of the wide layout (the narrow one has one).
    pub cols: usize,
    /// Height of a panel in pt (wide, narrow).
    pub panel_h: (f64, f64),
    /// Legend entries beyond the labelled series.
    pub legend: Vec<LegendEntry>,
    /// The panels share their x range.
    pub share_x: bool,
    /// The panels share their y range.
    pub share_y: bool,
    /// A colour bar under the panels.
    pub colorbar: Option<ColorBar>,
    /// A drawing made elsewhere (the diagram): (wide SVG, narrow SVG).
    pub raw: Option<(String, String)>,
    /// Extra rows of the CSV, already in its schema (a grid of values).
    pub extra_csv: Vec<String>,
    /// The rendered sizes in pt (wide, narrow), set when drawn.
    pub sizes: [(f64, f64); 2],
}

impl Figure {
    /// A figure of `panels` in `cols` columns.
    pub fn new(stem: &str, title: impl Into<String>, panels: Vec<Panel>, cols: usize) -> Self {
        Figure {
            stem: stem.into(),
            title: title.into(),
            caption: String::new(),
            panels,
            cols: cols.max(1),
            panel_h: (150.0, 150.0),
            legend: Vec::new(),
            share_x: false,
            share_y: false,
            colorbar: None,
            raw: None,
            extra_csv: Vec::new(),
            sizes: [(0.0, 0.0); 2],
        }
    }

    /// With a caption.
    pub fn caption(mut self, c: impl Into<String>) -> Self {
        self.caption = c.into();
        self
    }

    /// With panel heights (wide, narrow) in pt.
    pub fn heights(mut self, wide: f64, narrow: f64) -> Self {
        self.panel_h = (wide, narrow);
        self
    }
}

/// A number for a label, with `dec` decimals and a true minus sign.
pub fn fmt(v: f64, dec: usize) -> String {
    minus(&format!("{v:.dec$}"))
}

/// `s` with hyphen-minus signs as U+2212.
pub fn minus(s: &str) -> String {
    s.replace('-', "\u{2212}")
}

/// A tick label with `dec` decimals: a true minus sign, never "−0".
pub fn tick_text(v: f64, dec: usize) -> String {
    let s = format!("{v:.dec$}");
    if s.trim_start_matches('-')
        .chars()
        .all(|c| c == '0' || c == '.')
    {
        s.trim_start_matches('-').to_string()
    } else {
        minus(&s)
    }
}

/// An angle in radians with its degrees in parentheses: `1.0472 (60.0°)`.
pub fn rad(v: f64, dec: usize) -> String {
    format!("{} ({}°)", fmt(v, dec), fmt(v.to_degrees(), 1))
}

impl RefLine {
    /// With the digits of its position and its hover text.
    pub fn verified(mut self, d: Digits, title: impl Into<String>) -> Self {
        self.digits = d;
        self.title = title.into();
        self
    }

    /// With a CSV key.
    pub fn key(mut self, k: impl Into<String>) -> Self {
        self.key = k.into();
        self
    }
}

/// Time, in units of τ = √(r₁/g).
pub fn q_t() -> Quantity {
    Quantity::new("t", "tau", "t (τ)")
}

/// θ in radians.
pub fn q_theta() -> Quantity {
    Quantity::new("theta", "rad", "θ (rad)")
}

/// A force in units of m₁g.
pub fn q_force() -> Quantity {
    Quantity::new("force", "m1*g", "force (m₁g)")
}
