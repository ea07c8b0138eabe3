//! The vector PDF beside every SVG: the same drawing converted by svg2pdf
//! (through usvg), the page the SVG's size in pt (85 or 178 mm wide), text
//! kept as text in the embedded font (a subset of DejaVu Sans).

use super::canvas::FONT_BYTES;
use std::sync::{Arc, OnceLock};
use svg2pdf::usvg;

fn fonts() -> Arc<usvg::fontdb::Database> {
    static DB: OnceLock<Arc<usvg::fontdb::Database>> = OnceLock::new();
    DB.get_or_init(|| {
        let mut db = usvg::fontdb::Database::new();
        db.load_font_data(FONT_BYTES.to_vec());
        db.set_sans_serif_family("DejaVu Sans");
        Arc::new(db)
    })
    .clone()
}

/// The PDF of an SVG whose width and height are in pt: the page is that
/// size.
pub fn pdf(svg: &str) -> Result<Vec<u8>, String> {
    let opt = usvg::Options {
        fontdb: fonts(),
        font_family: "DejaVu Sans".into(),
        ..usvg::Options::default()
    };
    let tree = usvg::Tree::from_str(svg, &opt).map_err(|e| e.to_string())?;
    svg2pdf::to_pdf(
        &tree,
        svg2pdf::ConversionOptions::default(),
        // usvg reads the SVG's size in pt as CSS pixels (96 per inch):
        // at 96 dpi the page is the SVG's print size again
        svg2pdf::PageOptions { dpi: 96.0 },
    )
    .map_err(|e| format!("{e:?}"))
}

/// The page size of a PDF written by [`pdf`] (its first MediaBox), in pt.
pub fn media_box(pdf: &[u8]) -> Option<(f64, f64)> {
    let text = String::from_utf8_lossy(pdf);
    let i = text.find("/MediaBox")?;
    let rest = &text[i..];
    let (a, b) = (rest.find('[')?, rest.find(']')?);
    let v: Vec<f64> = rest[a + 1..b]
        .split_whitespace()
        .filter_map(|x| x.parse().ok())
        .collect();
    (v.len() == 4).then(|| (v[2] - v[0], v[3] - v[1]))
}
