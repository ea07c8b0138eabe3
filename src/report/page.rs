//! Tables and the pages (README.md, index.html, and Markdown documents such
//! as `audit.md` rendered as HTML pages of the report).

use super::model::Figure;

/// A table with a caption, rendered to Markdown and HTML alike.
#[derive(Debug, Clone)]
pub struct Table {
    /// Anchor id.
    pub id: String,
    /// Heading.
    pub title: String,
    /// Text before the table.
    pub intro: String,
    /// Column headers.
    pub header: Vec<String>,
    /// Rows of cells; a cell starting with `=` is a number (monospace,
    /// aligned on the decimal point).
    pub rows: Vec<Vec<String>>,
    /// Its numbers as CSV (file name in the report's directory; empty: none).
    pub csv: String,
}

/// A text section (heading and paragraphs or a list).
#[derive(Debug, Clone)]
pub struct Section {
    /// Heading.
    pub title: String,
    /// Paragraphs.
    pub paragraphs: Vec<String>,
    /// Bullet items.
    pub items: Vec<String>,
    /// Links (relative path, text), as bullet items after the others.
    pub links: Vec<(String, String)>,
}

/// What goes on a page, in order.
#[derive(Debug, Clone)]
pub enum Block {
    /// A table.
    Table(Table),
    /// A figure (its SVG, narrow SVG and CSV live in `figures/`).
    Figure(Figure),
    /// Text.
    Section(Section),
    /// A sub-heading.
    Heading(String),
}

/// Marks a cell as a number.
pub fn num(s: impl AsRef<str>) -> String {
    format!("={}", s.as_ref())
}

fn cell_md(c: &str) -> String {
    match c.strip_prefix('=') {
        Some(n) => format!("`{n}`"),
        None => c.replace('|', "\\|"),
    }
}

/// HTML escape.
pub fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// HTML-escaped text with `code` spans turned into <code> elements (or
/// MathML where they are equations).
fn esc_inline(s: &str) -> String {
    let mut out = String::new();
    for (i, part) in s.split('`').enumerate() {
        if i % 2 == 1 {
            out.push_str(&code_or_math(part));
        } else {
            out.push_str(&esc(part));
        }
    }
    out
}

/// A code span: MathML where it is an equation, plain text where it is
/// prose with symbols, else <code>.
fn code_or_math(part: &str) -> String {
    if super::math::is_equation(part) {
        super::math::mathml(part)
    } else if super::math::is_prose(part) {
        format!("<q>{}</q>", esc(part))
    } else {
        format!("<code>{}</code>", esc(part))
    }
}

/// Path of a figure (wide layout, 178 mm) relative to the pages.
pub fn figure_path(f: &Figure) -> String {
    format!("figures/{}.svg", f.stem)
}

/// Path of a figure's narrow layout (85 mm).
pub fn narrow_path(f: &Figure) -> String {
    format!("figures/{}.narrow.svg", f.stem)
}

/// Path of a figure's PDF (`narrow`: the 85 mm one).
pub fn pdf_path(f: &Figure, narrow: bool) -> String {
    if narrow {
        format!("figures/{}.narrow.pdf", f.stem)
    } else {
        format!("figures/{}.pdf", f.stem)
    }
}

/// Path of a figure's data (None: a drawing without data).
pub fn csv_path(f: &Figure) -> Option<String> {
    f.raw.is_none().then(|| format!("figures/{}.csv", f.stem))
}

fn fig_id(f: &Figure) -> String {
    format!("fig-{}", f.stem.replace('_', "-"))
}

/// Other pages of the report, linked from the index: (file, title).
pub type Pages = Vec<(String, String)>;

/// The Markdown page.
pub fn markdown(title: &str, intro: &[String], blocks: &[Block], pages: &Pages) -> String {
    let mut s = format!("# {title}\n\n");
    for p in intro {
        s.push_str(p);
        s.push_str("\n\n");
    }
    if !pages.is_empty() {
        s.push_str("Other pages: ");
        let links: Vec<String> = pages
            .iter()
            .map(|(f, t)| {
                // a page rendered from a Markdown document links to that document
                let target = match super::DOCUMENTS.iter().find(|d| d.1 == f) {
                    Some(d) => d.0.to_string(),
                    None => f.clone(),
                };
                format!("[{t}]({target})")
            })
            .collect();
        s.push_str(&links.join(", "));
        s.push_str(".\n\n");
    }
    // contents, with every table and figure
    s.push_str("Contents:\n\n");
    for b in blocks {
        match b {
            Block::Table(t) => s.push_str(&format!("  - [{}](#{})\n", t.title, t.id)),
            Block::Figure(f) => s.push_str(&format!(
                "  - figure: [{}](#{}) — `{}`\n",
                f.title,
                fig_id(f),
                figure_path(f)
            )),
            Block::Heading(h) => s.push_str(&format!("- {h}\n")),
            Block::Section(sec) => s.push_str(&format!("  - {}\n", sec.title)),
        }
    }
    s.push('\n');
    for b in blocks {
        match b {
            Block::Heading(h) => s.push_str(&format!("## {h}\n\n")),
            Block::Table(t) => table_md(&mut s, t),
            Block::Figure(f) => figure_md(&mut s, f),
            Block::Section(sec) => section_md(&mut s, sec),
        }
    }
    s
}

fn table_md(s: &mut String, t: &Table) {
    s.push_str(&format!("<a id=\"{}\"></a>\n\n### {}\n\n", t.id, t.title));
    if !t.intro.is_empty() {
        s.push_str(&t.intro);
        s.push_str("\n\n");
    }
    let row = |cells: &[String]| {
        let c: Vec<String> = cells.iter().map(|c| cell_md(c)).collect();
        format!("| {} |\n", c.join(" | "))
    };
    s.push_str(&row(&t.header));
    let align: Vec<&str> = (0..t.header.len())
        .map(|c| {
            if t.rows
                .iter()
                .any(|r| r.get(c).is_some_and(|x| x.starts_with('=')))
            {
                "--:|"
            } else {
                "---|"
            }
        })
        .collect();
    s.push_str(&format!("|{}\n", align.concat()));
    for r in &t.rows {
        s.push_str(&row(r));
    }
    if !t.csv.is_empty() {
        s.push_str(&format!("\n[the table as CSV]({})\n", t.csv));
    }
    s.push('\n');
}

fn figure_md(s: &mut String, f: &Figure) {
    s.push_str(&format!(
        "<a id=\"{}\"></a>\n\n### {}\n\n",
        fig_id(f),
        f.title
    ));
    s.push_str(&format!("![{}]({})\n\n", f.title, figure_path(f)));
    s.push_str(&format!("*{}*", f.caption));
    let mut extra = Vec::new();
    if let Some(c) = csv_path(f) {
        extra.push(format!("[data (CSV)]({c})"));
    }
    extra.push(format!("[PDF 178 mm]({})", pdf_path(f, false)));
    extra.push(format!("[PDF 85 mm]({})", pdf_path(f, true)));
    extra.push(format!("[85 mm layout]({})", narrow_path(f)));
    s.push_str(&format!(" {}", extra.join(" · ")));
    s.push_str("\n\n");
}

fn section_md(s: &mut String, sec: &Section) {
    s.push_str(&format!("### {}\n\n", sec.title));
    for p in &sec.paragraphs {
        s.push_str(p);
        s.push_str("\n\n");
    }
    for i in &sec.items {
        s.push_str(&format!("- {i}\n"));
    }
    for (href, text) in &sec.links {
        s.push_str(&format!("- [{text}]({href})\n"));
    }
    if !sec.items.is_empty() || !sec.links.is_empty() {
        s.push('\n');
    }
}

/// The page's style: readable from phone width (400 px) to desktop; numbers
/// in tables monospace, at the text's size, right-aligned on the decimal
/// point; on narrow screens each table row becomes a block of values, each
/// beside its column's name, so that nothing scrolls sideways.
pub const CSS: &str = "\
*{box-sizing:border-box}\
body{font-family:'DejaVu Sans',Verdana,Arial,sans-serif;max-width:1240px;margin:0 auto;padding:0.5em 1em 3em 1em;line-height:1.5;color:#111;font-size:16px;overflow-wrap:break-word}\
h1{font-size:1.55em;line-height:1.25}h2{margin-top:2em;border-bottom:1px solid #ccc}h3{margin-top:1.6em;font-size:1.12em}\
code{font-family:'DejaVu Sans Mono',Menlo,Consolas,monospace;font-size:0.92em}\
pre{overflow-x:auto;background:#f6f6f6;padding:0.5em}\
figure{margin:1em 0 2.2em 0}figure h3{margin-top:0}\
object.fig{display:block;width:100%;height:auto;border:1px solid #ddd;background:#fff}object.one{max-width:560px}\
object.narrow{display:none}\
figcaption{font-size:0.95em;color:#222;margin-top:0.5em}figcaption .data{display:inline-block}\
.scroll{overflow-x:auto;max-width:100%}\
table{border-collapse:collapse;margin:0.5em 0 1.5em 0;font-size:0.95em}\
th,td{border:1px solid #ccc;padding:3px 8px;text-align:left;vertical-align:top}th{background:#f3f3f3}\
td.num{text-align:right;font-family:'DejaVu Sans Mono',Menlo,Consolas,monospace;font-size:0.95em;white-space:pre}\
nav ul{padding-left:1.2em}nav li{margin:0.1em 0}\
details>summary{cursor:pointer;list-style-position:outside}details>summary h2{display:inline-block;margin:1.2em 0 0.3em 0;border:none}\
details{border-top:1px solid #ccc;margin-top:1em}\
.eq{display:inline}.eq math{font-size:1.05em;margin-right:0.25em}\
.eq :is(msub,msup,msubsup,munder,mover,munderover)>:not(:first-child){font-size:max(0.71em,11px)}\
p.data{font-size:0.95em;margin-top:-1em}\
@media (max-width:700px){\
body{padding:0.3em 0.6em 2em 0.6em;font-size:15px}\
object.wide{display:none}object.narrow{display:block}\
details>summary{list-style-position:inside;margin:1.2em 0 0.3em 0}details>summary h2{display:inline}\
table.data,table.data tbody,table.data tr,table.data td{display:block;width:100%}\
table.data thead{display:none}\
table.data tr{border:1px solid #ccc;margin:0 0 0.6em 0;padding:0.15em 0}\
table.data td{display:grid;grid-template-columns:minmax(6em,36%) minmax(0,1fr);column-gap:0.6em;align-items:baseline;border:none;padding:1px 8px;text-align:left;white-space:normal}\
table.data td::before{content:attr(data-label);font-family:'DejaVu Sans',Verdana,sans-serif;font-size:0.85em;color:#555}\
table.data td.num code,table.data td.num{white-space:normal;overflow-wrap:anywhere}\
}";

/// The head of an HTML page.
pub fn head(title: &str) -> String {
    format!(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <title>{}</title>\n<style>{CSS}</style>\n</head>\n<body>\n",
        esc(title)
    )
}

/// A number cell's text padded so that the decimal points of a column line
/// up in a monospace font (right-aligned cells): (integer part, fraction
/// with the point) widths of the column.
fn split_num(n: &str) -> (usize, usize) {
    let n = n.trim();
    let int_end = n.find(['.', 'e', 'E', ' ']).unwrap_or(n.len());
    let int = n[..int_end].chars().count();
    (int, n.chars().count() - int)
}

fn table_html(t: &Table) -> String {
    let mut s = String::new();
    s.push_str(&format!(
        "<h3 id=\"{}\">{}</h3>\n",
        esc(&t.id),
        esc(&t.title)
    ));
    if !t.intro.is_empty() {
        s.push_str(&format!("<p>{}</p>\n", esc_inline(&t.intro)));
    }
    // width of the fraction part per column, for decimal alignment
    let cols = t.header.len();
    let mut frac = vec![0usize; cols];
    for r in &t.rows {
        for (c, cell) in r.iter().enumerate().take(cols) {
            if let Some(n) = cell.strip_prefix('=') {
                frac[c] = frac[c].max(split_num(n).1);
            }
        }
    }
    s.push_str("<div class=\"scroll\"><table class=\"data\">\n<thead><tr>");
    for h in &t.header {
        s.push_str(&format!("<th>{}</th>", esc(h)));
    }
    s.push_str("</tr></thead>\n<tbody>\n");
    for r in &t.rows {
        s.push_str("<tr>");
        for (c, cell) in r.iter().enumerate() {
            let label = t.header.get(c).map(|h| esc(h)).unwrap_or_default();
            match cell.strip_prefix('=') {
                Some(n) => {
                    let pad = frac
                        .get(c)
                        .copied()
                        .unwrap_or(0)
                        .saturating_sub(split_num(n).1);
                    s.push_str(&format!(
                        "<td class=\"num\" data-label=\"{label}\">{}{}</td>",
                        esc(&n.replace('-', "\u{2212}")),
                        " ".repeat(pad)
                    ));
                }
                None => s.push_str(&format!(
                    "<td data-label=\"{label}\">{}</td>",
                    esc_inline(cell)
                )),
            }
        }
        s.push_str("</tr>\n");
    }
    s.push_str("</tbody></table></div>\n");
    if !t.csv.is_empty() {
        s.push_str(&format!(
            "<p class=\"data\"><a href=\"{}\">the table as CSV</a></p>\n",
            esc(&t.csv)
        ));
    }
    s
}

fn figure_html(f: &Figure) -> String {
    let id = fig_id(f);
    let mut s = format!("<figure id=\"{id}\">\n<h3>{}</h3>\n", esc(&f.title));
    let obj = |path: &str, class: &str, (w, h): (f64, f64)| {
        format!(
            "<object class=\"fig {class}\" type=\"image/svg+xml\" data=\"{p}\" style=\"aspect-ratio:{w:.2}/{h:.2}\" aria-label=\"{t}\">\
             <img src=\"{p}\" alt=\"{t}\" style=\"width:100%;height:auto\"></object>\n",
            p = esc(path),
            t = esc(&f.title)
        )
    };
    // a figure one journal column wide in both layouts (the diagram) is
    // shown at a column's size on a wide screen too
    let wide_class = if f.sizes[0].0 < 300.0 {
        "wide one"
    } else {
        "wide"
    };
    s.push_str(&obj(&figure_path(f), wide_class, f.sizes[0]));
    s.push_str(&obj(&narrow_path(f), "narrow", f.sizes[1]));
    s.push_str(&format!("<figcaption>{}", esc_inline(&f.caption)));
    let mut links = Vec::new();
    if let Some(c) = csv_path(f) {
        links.push(format!("<a href=\"{}\">data (CSV)</a>", esc(&c)));
    }
    links.push(format!(
        "PDF for print: <a href=\"{}\">178 mm</a>, <a href=\"{}\">85 mm</a>",
        esc(&pdf_path(f, false)),
        esc(&pdf_path(f, true))
    ));
    links.push(format!(
        "SVG: <a href=\"{}\">178 mm</a>, <a href=\"{}\">85 mm</a> (hover a curve or marker for its values)",
        esc(&figure_path(f)),
        esc(&narrow_path(f))
    ));
    s.push_str(&format!(
        " <span class=\"data\">{}</span></figcaption>\n</figure>\n",
        links.join(" · ")
    ));
    s
}

/// The HTML page (no scripts, no external resources).
pub fn html(title: &str, intro: &[String], blocks: &[Block], pages: &Pages) -> String {
    let mut s = head(title);
    s.push_str(&format!("<h1>{}</h1>\n", esc(title)));
    for p in intro {
        s.push_str(&format!("<p>{}</p>\n", esc_inline(p)));
    }
    if !pages.is_empty() {
        let links: Vec<String> = pages
            .iter()
            .map(|(f, t)| format!("<a href=\"{}\">{}</a>", esc(f), esc(t)))
            .collect();
        s.push_str(&format!("<p>Other pages: {}.</p>\n", links.join(", ")));
    }
    s.push_str("<nav><h2>Contents</h2><ul>\n");
    let mut open = false;
    for b in blocks {
        let item = match b {
            Block::Table(t) => Some(format!(
                "<li><a href=\"#{}\">{}</a></li>",
                esc(&t.id),
                esc(&t.title)
            )),
            Block::Figure(f) => Some(format!(
                "<li><a href=\"#{}\">{}</a></li>",
                esc(&fig_id(f)),
                esc(&f.title)
            )),
            Block::Heading(h) => {
                if open {
                    s.push_str("</ul></li>\n");
                }
                s.push_str(&format!(
                    "<li><a href=\"#{}\"><b>{}</b></a><ul>\n",
                    section_id(h),
                    esc(h)
                ));
                open = true;
                None
            }
            Block::Section(_) => None,
        };
        if let Some(i) = item {
            s.push_str(&i);
            s.push('\n');
        }
    }
    if open {
        s.push_str("</ul></li>\n");
    }
    s.push_str("</ul></nav>\n");
    let mut open_section = false;
    for b in blocks {
        match b {
            Block::Heading(h) => {
                if open_section {
                    s.push_str("</details>\n");
                }
                s.push_str(&format!(
                    "<details open id=\"{}\"><summary><h2>{}</h2></summary>\n",
                    section_id(h),
                    esc(h)
                ));
                open_section = true;
            }
            Block::Table(t) => s.push_str(&table_html(t)),
            Block::Figure(f) => s.push_str(&figure_html(f)),
            Block::Section(sec) => {
                s.push_str(&format!("<h3>{}</h3>\n", esc(&sec.title)));
                for p in &sec.paragraphs {
                    s.push_str(&format!("<p>{}</p>\n", esc_inline(p)));
                }
                if !sec.items.is_empty() || !sec.links.is_empty() {
                    s.push_str("<ul>\n");
                    for i in &sec.items {
                        s.push_str(&format!("<li>{}</li>\n", esc_inline(i)));
                    }
                    for (href, text) in &sec.links {
                        s.push_str(&format!(
                            "<li><a href=\"{}\">{}</a></li>\n",
                            esc(href),
                            esc(text)
                        ));
                    }
                    s.push_str("</ul>\n");
                }
            }
        }
    }
    if open_section {
        s.push_str("</details>\n");
    }
    s.push_str("</body>\n</html>\n");
    s
}

/// The anchor of a section heading.
fn section_id(h: &str) -> String {
    let id: String = super::model::ascii_key(&h.to_lowercase())
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '-' })
        .collect();
    format!("sec-{}", id.trim_matches('-'))
}

// ------------------------------------------------------------ Markdown

/// Inline Markdown: `code` (MathML where it is an equation), **bold**,
/// *emphasis*, [text](link).
fn md_inline(s: &str) -> String {
    let mut out = String::new();
    for (i, part) in s.split('`').enumerate() {
        if i % 2 == 1 {
            out.push_str(&code_or_math(part));
            continue;
        }
        let mut t = esc(part);
        t = pairs(&t, "**", "<strong>", "</strong>");
        t = pairs(&t, "*", "<em>", "</em>");
        t = links(&t);
        out.push_str(&t);
    }
    out
}

/// Replaces matched pairs of `mark` by the tags (an unmatched mark stays).
fn pairs(s: &str, mark: &str, open: &str, close: &str) -> String {
    let parts: Vec<&str> = s.split(mark).collect();
    if parts.len() < 3 {
        return s.to_string();
    }
    let mut out = String::new();
    let pairs_n = (parts.len() - 1) / 2 * 2;
    for (i, p) in parts.iter().enumerate() {
        if i > 0 {
            if i <= pairs_n {
                out.push_str(if i % 2 == 1 { open } else { close });
            } else {
                out.push_str(mark);
            }
        }
        out.push_str(p);
    }
    out
}

/// `[text](target)` into links; a target `x.md` of the report becomes `x.html`.
fn links(s: &str) -> String {
    let mut out = String::new();
    let mut rest = s;
    while let Some(a) = rest.find('[') {
        let Some(b) = rest[a..].find("](").map(|b| a + b) else {
            break;
        };
        let Some(c) = rest[b..].find(')').map(|c| b + c) else {
            break;
        };
        out.push_str(&rest[..a]);
        let text = &rest[a + 1..b];
        let mut target = rest[b + 2..c].to_string();
        if !target.contains("://") && target.ends_with(".md") {
            target = format!("{}.html", target.trim_end_matches(".md"));
        }
        out.push_str(&format!("<a href=\"{target}\">{text}</a>"));
        rest = &rest[c + 1..];
    }
    out.push_str(rest);
    out
}

fn md_row(line: &str) -> Vec<String> {
    let t = line.trim().trim_start_matches('|').trim_end_matches('|');
    // split on | not escaped
    let mut cells = Vec::new();
    let mut cur = String::new();
    let mut prev = ' ';
    for ch in t.chars() {
        if ch == '|' && prev != '\\' {
            cells.push(cur.trim().to_string());
            cur.clear();
        } else {
            cur.push(ch);
        }
        prev = ch;
    }
    cells.push(cur.trim().replace("\\|", "|"));
    cells
}

/// Whether `t` starts a numbered list item ("12. …").
fn numbered_item(t: &str) -> bool {
    t.split_once(". ")
        .is_some_and(|(a, _)| !a.is_empty() && a.chars().all(|c| c.is_ascii_digit()))
}

/// A fenced code block starting at line `i`; returns the line after it.
fn md_code(lines: &[&str], mut i: usize, body: &mut String) -> usize {
    let mut code = String::new();
    i += 1;
    while i < lines.len() && !lines[i].trim().starts_with("```") {
        code.push_str(&esc(lines[i]));
        code.push('\n');
        i += 1;
    }
    body.push_str(&format!("<pre><code>{code}</code></pre>\n"));
    i + 1
}

/// A heading of level `h` with an anchor made of its text.
fn md_heading(t: &str, h: usize, body: &mut String) {
    let text = t[h + 1..].trim();
    let id: String = text
        .to_lowercase()
        .chars()
        .map(|c| if c.is_alphanumeric() { c } else { '-' })
        .collect();
    body.push_str(&format!(
        "<h{h} id=\"{}\">{}</h{h}>\n",
        esc(id.trim_matches('-')),
        md_inline(text)
    ));
}

/// A table starting at line `i`; returns the line after it.
fn md_table(lines: &[&str], mut i: usize, body: &mut String) -> usize {
    let header = md_row(lines[i].trim());
    let mut rows = Vec::new();
    i += 1;
    if i < lines.len() && lines[i].trim().starts_with("|") && lines[i].contains("--") {
        i += 1;
    }
    while i < lines.len() && lines[i].trim().starts_with('|') {
        rows.push(md_row(lines[i]));
        i += 1;
    }
    body.push_str("<table class=\"data\">\n<thead><tr>");
    for h in &header {
        body.push_str(&format!("<th>{}</th>", md_inline(h)));
    }
    body.push_str("</tr></thead>\n<tbody>\n");
    for r in rows {
        body.push_str("<tr>");
        for (k, c) in r.iter().enumerate() {
            let label = header.get(k).map(|h| esc(h)).unwrap_or_default();
            body.push_str(&format!("<td data-label=\"{label}\">{}</td>", md_inline(c)));
        }
        body.push_str("</tr>\n");
    }
    body.push_str("</tbody></table>\n");
    i
}

/// One list item starting at line `i`, with its continuation lines: its
/// text and the line after it.
fn md_item(lines: &[&str], mut i: usize, bullet: bool) -> (String, usize) {
    // keep trailing spaces: two of them are a hard line break
    let full = lines[i].trim_start();
    let mut item = if bullet {
        full[2..].to_string()
    } else {
        full.split_once(". ")
            .map(|x| x.1)
            .unwrap_or(full)
            .to_string()
    };
    i += 1;
    // continuation lines (indented, or not blank and not a new item)
    while i < lines.len() {
        let c = lines[i];
        if c.trim().is_empty() {
            // a blank line inside an item continues only if indented text follows
            if i + 1 < lines.len() && lines[i + 1].starts_with("   ") {
                item.push_str("\n\n");
                i += 1;
                continue;
            }
            break;
        }
        if !c.starts_with("  ") {
            break;
        }
        let hard = item.ends_with("  ");
        item = item.trim_end().to_string();
        item.push_str(if hard { "<br>" } else { " " });
        item.push_str(c.trim());
        i += 1;
    }
    (item, i)
}

/// A bulleted or numbered list starting at line `i`; returns the line after it.
fn md_list(lines: &[&str], mut i: usize, bullet: bool, body: &mut String) -> usize {
    let tag = if bullet { "ul" } else { "ol" };
    body.push_str(&format!("<{tag}>\n"));
    while i < lines.len() {
        let t = lines[i].trim();
        let is_item = if bullet {
            t.starts_with("- ") || t.starts_with("* ")
        } else {
            numbered_item(t)
        };
        if !is_item || lines[i].starts_with("  ") {
            break;
        }
        let (item, next) = md_item(lines, i, bullet);
        i = next;
        let html = md_inline(item.trim_end()).replace("&lt;br&gt;", "<br>");
        body.push_str(&format!("<li>{html}</li>\n"));
        while i < lines.len() && lines[i].trim().is_empty() {
            // blank lines between items of one list
            let next = lines.get(i + 1).map(|x| x.trim()).unwrap_or("");
            let more = if bullet {
                next.starts_with("- ")
            } else {
                numbered_item(next)
            };
            if !more {
                break;
            }
            i += 1;
        }
    }
    body.push_str(&format!("</{tag}>\n"));
    i
}

/// A Markdown document (headings, paragraphs, lists, tables, code blocks,
/// inline code, bold, emphasis, links) as an HTML page of the report, with a
/// link back to the index.
pub fn markdown_page(md: &str, fallback_title: &str) -> String {
    let title = md
        .lines()
        .find_map(|l| l.strip_prefix("# "))
        .unwrap_or(fallback_title)
        .trim()
        .to_string();
    let mut body = String::new();
    let lines: Vec<&str> = md.lines().collect();
    let mut i = 0;
    let mut para: Vec<String> = Vec::new();
    let flush = |para: &mut Vec<String>, body: &mut String| {
        if !para.is_empty() {
            body.push_str(&format!("<p>{}</p>\n", para.join("\n")));
            para.clear();
        }
    };
    while i < lines.len() {
        let l = lines[i];
        let t = l.trim();
        let heading = (1..=4).find(|&n| t.starts_with(&format!("{} ", "#".repeat(n))));
        let bullet = t.starts_with("- ") || t.starts_with("* ");
        let list = (bullet || numbered_item(t)) && !l.starts_with("  ");
        if t.is_empty() || t.starts_with("```") || heading.is_some() || t.starts_with('|') || list {
            flush(&mut para, &mut body);
        }
        i = if t.is_empty() {
            i + 1
        } else if t.starts_with("```") {
            md_code(&lines, i, &mut body)
        } else if let Some(h) = heading {
            md_heading(t, h, &mut body);
            i + 1
        } else if t.starts_with('|') {
            md_table(&lines, i, &mut body)
        } else if list {
            md_list(&lines, i, bullet, &mut body)
        } else {
            para.push(md_inline(t));
            i + 1
        };
    }
    flush(&mut para, &mut body);
    let mut s = head(&title);
    s.push_str("<p><a href=\"index.html\">← the report</a></p>\n<div class=\"md\">\n");
    s.push_str(&body);
    s.push_str("</div>\n</body>\n</html>\n");
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn markdown_renders_its_structures() {
        let md = "# Title\n\nSome *text* with `code` and **bold**, see [the audit](audit.md).\n\n\
                  ## Part\n\n1. **One** — first  \n   second line\n\n2. Two\n\n- a\n- b\n\n| x | y |\n|---|--:|\n| 1 | a\\|b |\n";
        let h = markdown_page(md, "x");
        assert!(h.contains("<title>Title</title>"));
        assert!(h.contains("name=\"viewport\""));
        assert!(h.contains("<em>text</em>"));
        assert!(h.contains("<strong>bold</strong>"));
        assert!(h.contains("<a href=\"audit.html\">the audit</a>"));
        assert!(
            h.contains("<ol>\n<li><strong>One</strong> — first<br>second line</li>"),
            "{h}"
        );
        assert!(h.contains("<li>Two</li>\n</ol>"), "{h}");
        assert!(h.contains("<ul>\n<li>a</li>\n<li>b</li>\n</ul>"));
        assert!(h.contains(">a|b</td>"), "{h}");
    }

    #[test]
    fn numbers_align_on_the_decimal_point() {
        let t = Table {
            id: "t".into(),
            title: "t".into(),
            intro: String::new(),
            header: vec!["a".into()],
            rows: vec![vec![num("1.25")], vec![num("-10.5")], vec![num("3")]],
            csv: String::new(),
        };
        let h = table_html(&t);
        assert!(h.contains(">1.25</td>"), "{h}");
        assert!(h.contains(">\u{2212}10.5 </td>"), "{h}");
        assert!(h.contains(">3   </td>"), "{h}");
    }
}
