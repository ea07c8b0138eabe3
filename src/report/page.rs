//! Tables and the two pages (README.md, index.html) that show every figure.

use super::plot::Figure;

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
    /// Rows of cells; a cell starting with `=` is a number (monospace).
    pub rows: Vec<Vec<String>>,
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
    /// A figure (its SVG lives in `figures/`).
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

fn cell_html(c: &str) -> String {
    match c.strip_prefix('=') {
        Some(n) => format!("<td class=\"num\"><code>{}</code></td>", esc(n)),
        None => format!("<td>{}</td>", esc(c)),
    }
}

/// HTML-escaped text with `code` spans turned into <code> elements.
fn esc_inline(s: &str) -> String {
    let mut out = String::new();
    for (i, part) in s.split('`').enumerate() {
        if i % 2 == 1 {
            out.push_str(&format!("<code>{}</code>", esc(part)));
        } else {
            out.push_str(&esc(part));
        }
    }
    out
}

/// Path of a figure relative to the pages.
pub fn figure_path(f: &Figure) -> String {
    format!("figures/{}", f.file)
}

/// The Markdown page.
pub fn markdown(title: &str, intro: &[String], blocks: &[Block]) -> String {
    let mut s = format!("# {title}\n\n");
    for p in intro {
        s.push_str(p);
        s.push_str("\n\n");
    }
    // contents
    s.push_str("Contents:\n\n");
    for b in blocks {
        match b {
            Block::Table(t) => s.push_str(&format!("- [{}](#{})\n", t.title, t.id)),
            Block::Heading(h) => s.push_str(&format!("- {h}\n")),
            _ => {}
        }
    }
    s.push('\n');
    for b in blocks {
        match b {
            Block::Heading(h) => s.push_str(&format!("## {h}\n\n")),
            Block::Table(t) => {
                s.push_str(&format!("<a id=\"{}\"></a>\n\n### {}\n\n", t.id, t.title));
                if !t.intro.is_empty() {
                    s.push_str(&t.intro);
                    s.push_str("\n\n");
                }
                s.push_str(&format!(
                    "| {} |\n",
                    t.header
                        .iter()
                        .map(|h| cell_md(h))
                        .collect::<Vec<_>>()
                        .join(" | ")
                ));
                s.push_str(&format!("|{}\n", "---|".repeat(t.header.len())));
                for r in &t.rows {
                    s.push_str(&format!(
                        "| {} |\n",
                        r.iter().map(|c| cell_md(c)).collect::<Vec<_>>().join(" | ")
                    ));
                }
                s.push('\n');
            }
            Block::Figure(f) => {
                s.push_str(&format!("### {}\n\n", f.title));
                s.push_str(&format!("![{}]({})\n\n", f.title, figure_path(f)));
                s.push_str(&format!("*{}*\n\n", f.caption));
            }
            Block::Section(sec) => {
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
        }
    }
    s
}

const CSS: &str = "body{font-family:sans-serif;max-width:1280px;margin:1em auto;padding:0 1em;line-height:1.45;color:#111}\
h1{font-size:1.6em}h2{margin-top:2em;border-bottom:1px solid #ccc}h3{margin-top:1.6em}\
figure{margin:1em 0 2em 0}figure img{width:100%;height:auto;border:1px solid #ddd}\
figcaption{font-size:0.92em;color:#333;margin-top:0.4em}\
.scroll{overflow-x:auto}table{border-collapse:collapse;font-size:0.9em;margin:0.5em 0 1.5em 0}\
th,td{border:1px solid #ccc;padding:3px 7px;text-align:left;vertical-align:top}th{background:#f3f3f3}\
td.num code{font-size:0.95em;white-space:nowrap}nav li{margin:0.1em 0}";

/// The HTML page (no scripts, no external resources).
pub fn html(title: &str, intro: &[String], blocks: &[Block]) -> String {
    let mut s = String::new();
    s.push_str("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n");
    s.push_str(&format!("<title>{}</title>\n", esc(title)));
    s.push_str(&format!("<style>{CSS}</style>\n</head>\n<body>\n"));
    s.push_str(&format!("<h1>{}</h1>\n", esc(title)));
    for p in intro {
        s.push_str(&format!("<p>{}</p>\n", esc_inline(p)));
    }
    s.push_str("<nav><ul>\n");
    for b in blocks {
        match b {
            Block::Table(t) => s.push_str(&format!(
                "<li><a href=\"#{}\">{}</a></li>\n",
                esc(&t.id),
                esc(&t.title)
            )),
            Block::Figure(f) => s.push_str(&format!(
                "<li><a href=\"#fig-{}\">{}</a></li>\n",
                esc(f.file.trim_end_matches(".svg")),
                esc(&f.title)
            )),
            Block::Heading(h) => s.push_str(&format!("<li><b>{}</b></li>\n", esc(h))),
            Block::Section(_) => {}
        }
    }
    s.push_str("</ul></nav>\n");
    for b in blocks {
        match b {
            Block::Heading(h) => s.push_str(&format!("<h2>{}</h2>\n", esc(h))),
            Block::Table(t) => {
                s.push_str(&format!(
                    "<h3 id=\"{}\">{}</h3>\n",
                    esc(&t.id),
                    esc(&t.title)
                ));
                if !t.intro.is_empty() {
                    s.push_str(&format!("<p>{}</p>\n", esc(&t.intro)));
                }
                s.push_str("<div class=\"scroll\"><table>\n<tr>");
                for h in &t.header {
                    s.push_str(&format!("<th>{}</th>", esc(h)));
                }
                s.push_str("</tr>\n");
                for r in &t.rows {
                    s.push_str("<tr>");
                    for c in r {
                        s.push_str(&cell_html(c));
                    }
                    s.push_str("</tr>\n");
                }
                s.push_str("</table></div>\n");
            }
            Block::Figure(f) => {
                s.push_str(&format!(
                    "<figure id=\"fig-{}\">\n<h3>{}</h3>\n<img src=\"{}\" alt=\"{}\" width=\"{}\" height=\"{}\">\n<figcaption>{}</figcaption>\n</figure>\n",
                    esc(f.file.trim_end_matches(".svg")),
                    esc(&f.title),
                    esc(&figure_path(f)),
                    esc(&f.title),
                    f.size.0,
                    f.size.1,
                    esc(&f.caption)
                ));
            }
            Block::Section(sec) => {
                s.push_str(&format!("<h3>{}</h3>\n", esc(&sec.title)));
                for p in &sec.paragraphs {
                    s.push_str(&format!("<p>{}</p>\n", esc_inline(p)));
                }
                if !sec.items.is_empty() || !sec.links.is_empty() {
                    s.push_str("<ul>\n");
                    for i in &sec.items {
                        s.push_str(&format!("<li>{}</li>\n", esc(i)));
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
    s.push_str("</body>\n</html>\n");
    s
}
