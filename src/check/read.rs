//! Reading a candidate: a re-openable source (the check reads it twice when
//! it must find the candidate's parting before evaluating the oracle), its
//! header and its rows, one line at a time in bounded memory.

use super::{Limits, MODE};
use crate::error::{Error, Result};
use crate::exact::Exact;
use crate::golden::Case;
use rug::Float;
use std::io::{BufRead, Read};

/// Longest line of a candidate, in bytes.
pub const MAX_LINE_BYTES: u64 = 1 << 16;

/// The full column lists of the first golden schema. A candidate whose
/// header is exactly one of them is judged as schema 2 like any other
/// (these are also the columns the golden data's README lists: reading
/// them as schema 1 failed the oracle's own φ2); where its φ2 then fails,
/// the report says that schema 1's φ2 (the paper's gauge for a rolling
/// contact, r1 θ0/r2 below today's) is judged with `--schema 1`.
const V1_HEADERS: [&str; 2] = [
    "t,theta,theta_dot,theta_ddot,phi1,phi2,x1,x2,y2,F1,N1,F21,N12",
    "t,theta,theta_dot,theta_ddot,phi1,phi2,x1,x2,y2,F1,N1,F21,N12,s1,s12,work,mode",
];

/// A refusal of the candidate `source` (its name in full: a path is not
/// shortened, so the file is always named).
pub fn refuse(source: &str, allowed: impl ToString) -> Error {
    Error::InvalidParameter {
        name: "candidate".into(),
        value: source.to_string(),
        allowed: allowed.to_string(),
    }
}

/// A candidate that can be read from its start as often as needed.
pub trait Source {
    /// Its name in messages (a path, or `candidate`).
    fn name(&self) -> &str;
    /// A reader from the first byte.
    fn open(&self) -> Result<Box<dyn BufRead + '_>>;
    /// Whether messages name a row's line as well (a file the user can open
    /// at that line; not text made in memory, e.g. from Python arrays).
    fn lines(&self) -> bool {
        true
    }
}

/// A candidate held in memory as CSV text.
pub struct Text<'a> {
    /// The CSV text.
    pub text: &'a str,
    /// Its name in messages.
    pub name: String,
}

impl Source for Text<'_> {
    fn name(&self) -> &str {
        &self.name
    }
    fn lines(&self) -> bool {
        false
    }
    fn open(&self) -> Result<Box<dyn BufRead + '_>> {
        Ok(Box::new(std::io::Cursor::new(self.text.as_bytes())))
    }
}

/// A candidate CSV file, opened afresh for every pass.
pub struct File {
    /// The path.
    pub path: std::path::PathBuf,
    /// Its name in messages.
    pub name: String,
}

impl File {
    /// The file at `path`, named by its path.
    pub fn new(path: impl Into<std::path::PathBuf>) -> Self {
        let path = path.into();
        let name = path.display().to_string();
        File { path, name }
    }
}

impl Source for File {
    fn name(&self) -> &str {
        &self.name
    }
    fn open(&self) -> Result<Box<dyn BufRead + '_>> {
        // a file that cannot be opened is an input file's error (as a
        // parameter file's), not a malformed candidate
        let f = std::fs::File::open(&self.path).map_err(|e| Error::Io {
            path: self.name.clone(),
            what: format!("cannot be read: {e}"),
        })?;
        Ok(Box::new(std::io::BufReader::with_capacity(1 << 16, f)))
    }
}

/// One candidate cell: (golden column index, its text, its value; NaN for
/// the `mode` column's text).
pub type Cell = (usize, String, f64);

/// The header of a candidate.
#[derive(Debug, Clone)]
pub struct Header {
    /// Column names, in the candidate's order.
    pub cols: Vec<String>,
    /// Their indices in [`super::known_columns`].
    pub idx: Vec<usize>,
    /// The position of `t`.
    pub t_col: usize,
    /// Added to a candidate's φ2 (schema 1: the paper's gauge).
    pub phi2_shift: Float,
    /// The header is a full column list of schema 1 and no schema was
    /// given: judged as schema 2, with a note where φ2 fails.
    pub schema1_like: bool,
}

impl Header {
    /// Whether the candidate has the column of [`super::known_columns`] index `gi`.
    pub fn has(&self, gi: usize) -> bool {
        self.idx.contains(&gi)
    }
}

/// Rows of a candidate, read one at a time.
pub struct Rows<'a> {
    reader: Box<dyn BufRead + 'a>,
    buf: Vec<u8>,
    source: String,
    /// The header.
    pub header: Header,
    /// Data rows read so far.
    pub rows: usize,
    /// Lines of the file read so far (the header and blank lines count):
    /// a row's line, for messages that point into the file.
    line: usize,
    /// Whether messages name the line ([`Source::lines`]).
    show_lines: bool,
    max_rows: usize,
    /// The previous row's time (rows must be in time order).
    prev_t: Option<Exact>,
}

impl<'a> Rows<'a> {
    /// Opens `src` and reads its header, checked against the known columns.
    pub fn open(src: &'a dyn Source, case: &Case, lim: &Limits) -> Result<Rows<'a>> {
        let source = src.name().to_string();
        let mut reader = src.open()?;
        let mut buf = Vec::new();
        let mut line = 0usize;
        let header = loop {
            let next = next_line(&mut reader, &mut buf, &source, || {
                format!("the header row (line {})", line + 1)
            })?;
            line += 1;
            match next {
                None => return Err(refuse(&source, "is empty; expected a header row")),
                Some(l) if l.trim().is_empty() => continue,
                Some(l) => break crate::model::input::strip_bom(&l).to_string(),
            }
        };
        let header = parse_header(&header, &source, case, lim)?;
        Ok(Rows {
            reader,
            buf,
            source,
            header,
            rows: 0,
            line,
            show_lines: src.lines(),
            max_rows: lim.max_rows,
            prev_t: None,
        })
    }

    /// Refuses a candidate with more than `max_rows` data rows, counting its
    /// non-blank lines after the header without parsing them: done before
    /// any oracle work, so that a file too long is refused at once rather
    /// than after the rows before the limit were judged.
    ///
    /// Errors: the refusal; a read error.
    pub fn count_within_limit(mut self) -> Result<()> {
        let mut n = 0usize;
        let mut at = self.line;
        let lines = self.show_lines;
        while let Some(line) = next_line(&mut self.reader, &mut self.buf, &self.source, || {
            format!("row {}", RowLabel::new(n + 1, lines.then_some(at + 1)))
        })? {
            at += 1;
            if line.trim().is_empty() {
                continue;
            }
            n += 1;
            if n > self.max_rows {
                return Err(refuse(
                    &self.source,
                    format!(
                        "has more than {} data rows (raise --max-rows, at most {})",
                        self.max_rows,
                        super::MAX_ROWS_LIMIT
                    ),
                ));
            }
            if n % 65536 == 0 {
                crate::cancel::check()?;
            }
        }
        Ok(())
    }

    /// The last data row read, as messages name it: its number among the
    /// data rows, and its line in a file ("3 (line 5)").
    pub fn label(&self) -> RowLabel {
        RowLabel {
            row: self.rows,
            line: self.show_lines.then_some(self.line),
        }
    }

    /// The next data row: (its 1-based number, t, the other cells).
    pub fn next_row(&mut self) -> Result<Option<(usize, Exact, Vec<Cell>)>> {
        loop {
            let (rows, at, lines) = (self.rows, self.line, self.show_lines);
            let Some(line) = next_line(&mut self.reader, &mut self.buf, &self.source, || {
                format!("row {}", RowLabel::new(rows + 1, lines.then_some(at + 1)))
            })?
            else {
                return Ok(None);
            };
            self.line += 1;
            if line.trim().is_empty() {
                continue;
            }
            self.rows += 1;
            if self.rows > self.max_rows {
                return Err(refuse(
                    &self.source,
                    format!(
                        "has more than {} data rows (raise --max-rows, at most {})",
                        self.max_rows,
                        super::MAX_ROWS_LIMIT
                    ),
                ));
            }
            if self.rows % 4096 == 0 {
                crate::cancel::check()?;
            }
            let row = self.label();
            let (t, cells) = parse_row(&line, row, &self.header, &self.source)?;
            if t.signum() < 0 {
                return Err(refuse(
                    &self.source,
                    format!("row {row}: t = {t} is before the start (t must be >= 0)"),
                ));
            }
            if let Some(p) = &self.prev_t {
                if t.coef < p.coef {
                    return Err(refuse(
                        &self.source,
                        format!(
                            "row {row}: t = {t} is before the previous row's t = {p}: rows must be \
                             in time order (equal times are allowed)"
                        ),
                    ));
                }
            }
            self.prev_t = Some(t.clone());
            return Ok(Some((self.rows, t, cells)));
        }
    }
}

fn parse_header(line: &str, source: &str, case: &Case, lim: &Limits) -> Result<Header> {
    // a CR inside the line: the file's lines end in CR alone (old Mac), and
    // the whole file reads as one header ("unknown column \"theta\r0\"")
    if line.trim_end_matches('\r').contains('\r') {
        return Err(refuse(
            source,
            "has carriage returns (CR) inside its header line: its lines end in CR alone; \
             lines must end in LF or CR LF",
        ));
    }
    let cols: Vec<String> = line
        .split(',')
        .map(|c| c.trim().trim_matches('"').to_string())
        .collect();
    let known = super::known_columns();
    let schema1 = lim.schema == Some(1);
    let schema1_like = lim.schema.is_none() && V1_HEADERS.contains(&cols.join(",").as_str());
    // φ2 of schema 1: the paper's gauge for a contact that starts rolling
    let phi2_shift = if schema1 && *case.model.contact() != crate::model::Law::Frictionless {
        let pr = case.model.params();
        let th0 = case.model.start().theta0.to_float(256);
        Float::with_val(256, &pr.r1) * th0 / Float::with_val(256, &pr.r2)
    } else {
        Float::new(256)
    };
    let mut idx = Vec::new();
    for c in &cols {
        match known.iter().position(|g| g == c) {
            Some(i) if idx.contains(&i) => {
                return Err(refuse(source, format!("has the column {c:?} twice")))
            }
            Some(i) => idx.push(i),
            None => {
                return Err(refuse(
                    source,
                    format!("unknown column {c:?}; allowed: {}", known.join(", ")),
                ))
            }
        }
    }
    let t_col = cols
        .iter()
        .position(|c| c == "t")
        .ok_or_else(|| refuse(source, "needs a column named t"))?;
    if cols.len() < 2 {
        return Err(refuse(
            source,
            format!(
                "has only the column t: nothing to compare (add any of {})",
                known[1..].join(", ")
            ),
        ));
    }
    Ok(Header {
        cols,
        idx,
        t_col,
        phi2_shift,
        schema1_like,
    })
}

/// Reads one line of at most [`MAX_LINE_BYTES`] (without its line end);
/// `None` at the end of the input. `which` names the line for a refusal
/// ("data row 3 (line 5)", as every refusal names it).
fn next_line<R: BufRead + ?Sized>(
    r: &mut R,
    buf: &mut Vec<u8>,
    source: &str,
    which: impl Fn() -> String,
) -> Result<Option<String>> {
    buf.clear();
    let n = r
        .take(MAX_LINE_BYTES + 1)
        .read_until(b'\n', buf)
        .map_err(|e| Error::Io {
            path: source.to_string(),
            what: format!("cannot be read: {e}"),
        })?;
    if n == 0 {
        return Ok(None);
    }
    if buf.len() as u64 > MAX_LINE_BYTES {
        return Err(refuse(
            source,
            format!("{} is longer than {MAX_LINE_BYTES} bytes", which()),
        ));
    }
    let text = std::str::from_utf8(buf).map_err(|_| refuse(source, "is not UTF-8 text"))?;
    Ok(Some(text.trim_end_matches(['\n', '\r']).to_string()))
}

/// One data row (`row` names it in messages) parsed against the header.
/// A data row as messages name it: its number among the data rows, and its
/// line in a file ("3 (line 5)"; arrays from Python have no lines). Kept for
/// every row, written out only in a message.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RowLabel {
    /// The row's 1-based number among the data rows.
    pub row: usize,
    line: Option<usize>,
}

impl RowLabel {
    /// Row `row`, on line `line` of its file if it has lines.
    pub fn new(row: usize, line: Option<usize>) -> Self {
        RowLabel { row, line }
    }

    /// The row's line in its file, if it has one.
    pub fn line(&self) -> Option<usize> {
        self.line
    }
}

impl std::fmt::Display for RowLabel {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.line {
            Some(l) => write!(f, "{} (line {l})", self.row),
            None => write!(f, "{}", self.row),
        }
    }
}

fn parse_row(line: &str, row: RowLabel, h: &Header, source: &str) -> Result<(Exact, Vec<Cell>)> {
    let cells: Vec<&str> = line.split(',').map(|c| c.trim()).collect();
    if cells.len() != h.cols.len() {
        return Err(refuse(
            source,
            format!(
                "row {row} has {} fields, the header {}",
                cells.len(),
                h.cols.len()
            ),
        ));
    }
    let t = Exact::parse("t", cells[h.t_col], false).map_err(|_| {
        refuse(
            source,
            format!(
                "row {row}: t = {:?} is not a number",
                crate::error::shorten(cells[h.t_col])
            ),
        )
    })?;
    let mut vals = Vec::with_capacity(cells.len() - 1);
    for (k, cell) in cells.iter().enumerate() {
        if k == h.t_col {
            continue;
        }
        if h.idx[k] == MODE {
            let text = cell.trim_matches('"');
            // a mode the model has (flight, or FLOOR/CONTACT of stick,
            // slip+, slip-, slip, held): anything else is bad input, not
            // a change of mode to judge
            if crate::motion::Phase::parse(text).is_none() {
                return Err(refuse(
                    source,
                    format!(
                        "row {row}, column mode: {:?} is not a mode (allowed: flight, or \
                         FLOOR/CONTACT with each of stick, slip+, slip-, slip, held, e.g. \
                         stick/slip+)",
                        crate::error::shorten(text)
                    ),
                ));
            }
            vals.push((MODE, text.to_string(), f64::NAN));
            continue;
        }
        let v: f64 = cell.parse().map_err(|_| {
            refuse(
                source,
                format!(
                    "row {row}, column {}: {:?} is not a number",
                    h.cols[k],
                    crate::error::shorten(cell)
                ),
            )
        })?;
        if !v.is_finite() {
            return Err(refuse(
                source,
                format!(
                    "row {row}, column {}: {:?} is not finite",
                    h.cols[k],
                    crate::error::shorten(cell)
                ),
            ));
        }
        // the value is read exactly in the comparison: it must be a decimal
        if Exact::parse(&h.cols[k], cell, false).is_err() {
            return Err(refuse(
                source,
                format!(
                    "row {row}, column {}: {:?} is not a decimal number",
                    h.cols[k],
                    crate::error::shorten(cell)
                ),
            ));
        }
        vals.push((h.idx[k], cell.to_string(), v));
    }
    Ok((t, vals))
}
