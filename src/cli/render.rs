//! The one answer, printed: text, JSON or CSV, the same for every contact
//! law.

use super::Format;
use cylroll::numeric::verify::Verified;
use cylroll::oracle::rigorous::Proved;
use cylroll::oracle::{Answer, Question};
use serde_json::{json, Map, Value};

/// The answer in the requested format (`trajectory`'s tables are printed
/// by [`super::stream`], from [`table_parts`] and [`rows_text`]).
pub fn render(mut a: Answer, format: Format) -> String {
    debug_assert!(
        a.question != Question::Trajectory,
        "tables go through stream"
    );
    // a finding is stated once, however many routes reached it
    let mut seen = std::collections::HashSet::new();
    a.notes.retain(|n| seen.insert(n.clone()));
    match format {
        Format::Text => text(&a, None),
        Format::Json => json_text(&a, None).0,
        Format::Csv => csv(&a),
    }
}

/// What the text before and after a trajectory's rows says of all of them:
/// per column, the fewest digits verified, the largest error bound, the
/// cells printed 0 only to within a bound, the fewest digits proved.
#[derive(Default)]
pub struct RowStats {
    /// Rows seen.
    pub rows: usize,
    /// The numeric columns.
    names: Vec<String>,
    digits: Vec<Option<u32>>,
    err: Vec<Option<rug::Float>>,
    zeros: Vec<(usize, Option<rug::Float>)>,
    /// Per proved column (in the order first met): the fewest digits.
    proved: Vec<(String, u32)>,
    /// The fewest digits of a proved cell not printed 0.
    least_proved: Option<u32>,
    /// Some rows were proved (`--rigorous`).
    proved_any: bool,
}

impl RowStats {
    /// Adds the rows of `a` (a trajectory, or a block of one).
    pub fn add(&mut self, a: &Answer) {
        let n = value_columns(a).len();
        self.names = value_columns(a);
        if self.digits.is_empty() {
            self.digits = vec![None; n];
            self.err = vec![None; n];
            self.zeros = vec![(0, None); n];
        }
        for r in &a.rows {
            self.rows += 1;
            for (j, v) in r.values.iter().enumerate().take(n) {
                if v.digits > 0 {
                    self.digits[j] = Some(self.digits[j].map_or(v.digits, |d| d.min(v.digits)));
                } else if v.text == "0" && !v.err_bound.is_zero() {
                    let z = &mut self.zeros[j];
                    z.0 += 1;
                    if z.1.as_ref().is_none_or(|w| v.err_bound > *w) {
                        z.1 = Some(v.err_bound.clone());
                    }
                }
                if self.err[j].as_ref().is_none_or(|e| v.err_bound > *e) {
                    self.err[j] = Some(v.err_bound.clone());
                }
            }
        }
        self.proved_any |= !a.proved_rows.is_empty();
        for row in &a.proved_rows {
            for p in row.iter().filter(|p| self.names.contains(&p.name)) {
                match self.proved.iter_mut().find(|(c, _)| *c == p.name) {
                    Some((_, d)) => *d = (*d).min(p.shown.digits),
                    None => self.proved.push((p.name.clone(), p.shown.digits)),
                }
                if p.shown.text != "0" {
                    self.least_proved = Some(
                        self.least_proved
                            .map_or(p.shown.digits, |d| d.min(p.shown.digits)),
                    );
                }
            }
        }
    }
}

/// A trajectory's text before its rows and after them, for the rows that
/// `stats` summarises (`a`'s own rows are not printed).
pub fn table_parts(a: &Answer, format: Format, stats: &RowStats) -> (String, String) {
    let mut a2 = a.clone();
    let mut seen = std::collections::HashSet::new();
    a2.notes.retain(|n| seen.insert(n.clone()));
    a2.rows = Vec::new();
    a2.proved_rows = Vec::new();
    match format {
        Format::Text => {
            let all = text(&a2, Some(stats));
            let cut = all.find(ROWS_MARK).unwrap_or(all.len());
            let tail = all[cut..].replacen(ROWS_MARK, "", 1);
            (all[..cut].to_string(), tail)
        }
        Format::Json => json_text(&a2, Some(stats)),
        Format::Csv => (csv(&a2), String::new()),
    }
}

/// Where the rows go in the text form.
const ROWS_MARK: &str = "\u{0}ROWS\u{0}";

/// The rows of `a` in `format`, as they stand between the two parts of
/// [`table_parts`]; `first`: these are the first rows of the table (JSON
/// separates rows by commas).
pub fn rows_text(a: &Answer, format: Format, first: bool) -> String {
    // room for the cells and their separators of a text or CSV table (a
    // long table's text would be copied at every doubling)
    let cells: usize = a
        .rows
        .iter()
        .map(|r| r.values.iter().map(|v| v.text.len() + 1).sum::<usize>() + 16)
        .sum();
    let mut out = String::with_capacity(cells);
    // the columns once for every row (a row's cells are written straight
    // into `out`: a table of 10^5 rows is the common case)
    let cols = columns(a);
    let sep = match format {
        Format::Text => '\t',
        _ => ',',
    };
    for i in 0..a.rows.len() {
        match format {
            Format::Text | Format::Csv => {
                row_cells(a, i, &cols, |k, cell| {
                    if k > 0 {
                        out.push(sep);
                    }
                    out.push_str(cell);
                });
                out.push('\n');
            }
            Format::Json => {
                if !(first && i == 0) {
                    out.push(',');
                }
                out.push('\n');
                let pretty = serde_json::to_string_pretty(&row_json(a, i)).unwrap_or_default();
                for (k, line) in pretty.lines().enumerate() {
                    if k > 0 {
                        out.push('\n');
                    }
                    out.push_str("    ");
                    out.push_str(line);
                }
            }
        }
    }
    out
}

/// Row `i` of `a` as a JSON object.
fn row_json(a: &Answer, i: usize) -> Value {
    let r = &a.rows[i];
    let mut row = Map::new();
    let mut zeros = Map::new();
    let mut enc = Map::new();
    let cols = columns(a);
    let mode_at = cols.iter().position(|c| c == "mode");
    for (j, v) in r.values.iter().enumerate() {
        if mode_at == Some(j) {
            row.insert("mode".into(), r.phase.tag().into());
        }
        match proved_cell(a, i, &v.name) {
            Some(p) => {
                row.insert(v.name.clone(), p.shown.text.clone().into());
                enc.insert(v.name.clone(), enclosure_json(p, a.digits));
            }
            None => {
                row.insert(v.name.clone(), v.text.clone().into());
            }
        }
        if v.digits == 0 && v.text == "0" && !v.err_bound.is_zero() {
            zeros.insert(v.name.clone(), v.err_text().into());
        }
    }
    if mode_at.is_some_and(|k| k >= r.values.len()) {
        row.insert("mode".into(), r.phase.tag().into());
    }
    if !zeros.is_empty() {
        row.insert("zero_within".into(), zeros.into());
    }
    if !enc.is_empty() {
        row.insert("enclosures".into(), enc.into());
    }
    row.into()
}

/// The table's columns, in order: those asked (every column and `mode`
/// unless `--columns` chose).
fn columns(a: &Answer) -> Vec<String> {
    if a.columns.is_empty() {
        cylroll::oracle::all_columns()
    } else {
        a.columns.clone()
    }
}

/// The table's numeric columns (all but `mode`), in order: the values of
/// each row.
fn value_columns(a: &Answer) -> Vec<String> {
    columns(a).into_iter().filter(|c| c != "mode").collect()
}

/// The proved cell of a row's column, if the row is enclosed.
fn proved_cell<'a>(a: &'a Answer, row: usize, col: &str) -> Option<&'a Proved> {
    a.proved_rows
        .get(row)
        .and_then(|r| r.iter().find(|p| p.name == col))
}

/// Calls `cell(k, text)` for each cell of row `i` in the order of `cols`
/// (the answer's [`columns`]): the proved digits where the row is enclosed.
fn row_cells(a: &Answer, i: usize, cols: &[String], mut cell: impl FnMut(usize, &str)) {
    let r = &a.rows[i];
    let mut vals = r.values.iter();
    let proved = !a.proved_rows.is_empty();
    for (k, c) in cols.iter().enumerate() {
        if c == "mode" {
            cell(k, &r.phase.tag());
            continue;
        }
        match vals.next() {
            Some(v) => match proved.then(|| proved_cell(a, i, &v.name)).flatten() {
                Some(p) => cell(k, &p.shown.text),
                None => cell(k, &v.text),
            },
            None => cell(k, ""),
        }
    }
}

fn laws_line(a: &Answer) -> String {
    let m = &a.model;
    let mut s = format!("# contacts: floor {}, cylinders {}", m.floor(), m.contact());
    if let Some(sm) = a.start_mode {
        s.push_str(&format!("; start mode {}", sm.tag()));
    }
    s.push_str(&format!("; branch {}", a.branch.name()));
    if let Some(e) = a.end {
        s.push_str(&format!("; the motion ends at the {}", e.name()));
    }
    s.push('\n');
    s
}

fn text(a: &Answer, stats: Option<&RowStats>) -> String {
    let mut out = String::new();
    out.push_str(&format!(
        "# cylroll {} — {}\n",
        a.question.name(),
        a.model.describe()
    ));
    out.push_str(&laws_line(a));
    out.push_str(&format!(
        "# {} significant digits requested; each value below is verified to the digits printed\n",
        a.digits
    ));
    if !a.proved.is_empty() {
        out.push_str("# --rigorous: each value shows the digits its interval enclosure proves (directed rounding)\n");
    }
    let w = a.values.iter().map(|v| v.name.len()).max().unwrap_or(0);
    for (i, v) in a.values.iter().enumerate() {
        if let Some(pr) = a.proved.get(i) {
            let line = match pr {
                Some(pv) => {
                    let (mid, rad) = pv.texts(a.digits);
                    format!(
                        "{:w$} = {}  [proved: {} digits, in {} ± {}; verified: {} digits]\n",
                        v.name,
                        pv.shown.text,
                        pv.shown.digits,
                        mid,
                        rad,
                        v.digits,
                        w = w
                    )
                }
                None => format!(
                    "{:w$} = {}  [verified: {} digits; not enclosed]\n",
                    v.name,
                    v.text,
                    v.digits,
                    w = w
                ),
            };
            out.push_str(&line);
            continue;
        }
        out.push_str(&format!(
            "{:w$} = {}  {}\n",
            v.name,
            v.text,
            value_note(v),
            w = w
        ));
    }
    if let Some(p) = a.phase {
        out.push_str(&format!("mode at the angle: {p}\n"));
    }
    for (i, e) in a.events.iter().enumerate() {
        out.push_str(&format!(
            "event {}: {}{} at t = {} [{}], theta = {} [{}]{}{}\n",
            i + 1,
            e.kind.name(),
            e.which
                .map(|w| format!(" ({})", w.name()))
                .unwrap_or_default(),
            e.t.text,
            digits_word(e.t.digits),
            e.theta.text,
            digits_word(e.theta.digits),
            e.phase
                .map(|m| format!(" -> {m}"))
                .unwrap_or_else(|| " (end of the model)".into()),
            if e.also.is_empty() {
                String::new()
            } else {
                format!("; also consistent there: {}", e.also.join(", "))
            }
        ));
    }
    if let (Question::Trajectory, Some(stats)) = (a.question, stats) {
        out.push_str(&columns(a).join("\t"));
        out.push('\n');
        out.push_str(ROWS_MARK);
        if stats.proved_any {
            let least = stats.least_proved.unwrap_or(a.digits);
            out.push_str(&format!(
                "note: --rigorous: every enclosed cell shows the digits its interval enclosure proves (at least {least} significant digits)\n"
            ));
        }
        for z in zero_cells(stats) {
            out.push_str(&format!("note: {z}\n"));
        }
    }
    for n in &a.notes {
        out.push_str(&format!("note: {n}\n"));
    }
    out
}

fn value_note(v: &Verified) -> String {
    if v.text.starts_with(">=") {
        "[a lower bound: the normal force is 0 to within its error bound]".to_string()
    } else if v.digits == 0 {
        format!("[indistinguishable from 0: |x| <= {}]", v.err_text())
    } else {
        format!("[{}; |err| <= {}]", digits_word(v.digits), v.err_text())
    }
}

/// `1 digit`, `N digits`.
fn digits_word(n: u32) -> String {
    if n == 1 {
        "1 digit".into()
    } else {
        format!("{n} digits")
    }
}

/// `{"mid": …, "rad": …}` of an enclosure.
fn enclosure_json(pv: &Proved, digits: u32) -> Value {
    let (mid, rad) = pv.texts(digits);
    json!({"mid": mid, "rad": rad})
}

fn json_text(a: &Answer, stats: Option<&RowStats>) -> (String, String) {
    let mut o = Map::new();
    o.insert("command".into(), a.question.name().into());
    let mut m = Map::new();
    for (k, v) in a.model.echo() {
        m.insert(k.into(), v.into());
    }
    o.insert("model".into(), m.into());
    o.insert("branch".into(), a.branch.name().into());
    o.insert("digits_requested".into(), a.digits.to_string().into());
    o.insert("start_mode".into(), a.start_mode.map(|s| s.tag()).into());
    if matches!(a.question, Question::Separation | Question::Trajectory) {
        o.insert("end".into(), a.end.map(|e| e.name()).into());
        let evs: Vec<Value> = a
            .events
            .iter()
            .map(|e| {
                let mut j = json!({
                    "kind": e.kind.name(),
                    "contact": e.which.map(|w| w.name()),
                    "mode": e.phase.map(|p| p.tag()),
                    "t": e.t.text,
                    "theta": e.theta.text,
                    "digits_verified": {"t": e.t.digits.to_string(), "theta": e.theta.digits.to_string()},
                    "error_bounds": {"t": e.t.err_text(), "theta": e.theta.err_text()},
                });
                if !e.also.is_empty() {
                    j["alternatives"] = e.also.clone().into();
                }
                j
            })
            .collect();
        o.insert("events".into(), evs.into());
    }
    if let Some(p) = a.phase {
        o.insert("mode".into(), p.tag().into());
    }
    let mut verified = Map::new();
    let mut errs = Map::new();
    let mut rig = Map::new();
    let mut encl = Map::new();
    let mut lower = Map::new();
    for (i, v) in a.values.iter().enumerate() {
        match a.proved.get(i) {
            Some(Some(pv)) => {
                o.insert(v.name.clone(), pv.shown.text.clone().into());
                rig.insert(v.name.clone(), pv.shown.digits.to_string().into());
                encl.insert(v.name.clone(), enclosure_json(pv, a.digits));
            }
            Some(None) => {
                o.insert(v.name.clone(), v.text.clone().into());
                rig.insert(v.name.clone(), Value::Null);
            }
            None => {
                o.insert(v.name.clone(), v.text.clone().into());
            }
        }
        verified.insert(v.name.clone(), v.digits.to_string().into());
        errs.insert(v.name.clone(), v.err_text().into());
        if let Some(b) = v.text.strip_prefix(">=") {
            lower.insert(v.name.clone(), b.into());
        }
    }
    if !lower.is_empty() {
        o.insert("lower_bounds".into(), lower.into());
    }
    let stats = stats.filter(|_| a.question == Question::Trajectory);
    if let Some(stats) = stats {
        o.insert(
            "columns".into(),
            columns(a)
                .into_iter()
                .map(Value::from)
                .collect::<Vec<_>>()
                .into(),
        );
        o.insert("rows".into(), ROWS_MARK.into());
        for (j, c) in value_columns(a).iter().enumerate() {
            verified.insert(
                c.to_string(),
                stats
                    .digits
                    .get(j)
                    .copied()
                    .flatten()
                    .map_or("0".to_string(), |d| d.to_string())
                    .into(),
            );
            if let Some(Some(e)) = stats.err.get(j) {
                errs.insert(c.to_string(), cylroll::numeric::decimal::short(e).into());
            }
        }
        for (name, d) in &stats.proved {
            rig.insert(name.clone(), d.to_string().into());
        }
    }
    if !a.proved.is_empty() || stats.is_some_and(|s| s.proved_any) {
        o.insert("digits_rigorous".into(), rig.into());
        if !encl.is_empty() {
            o.insert("enclosures".into(), encl.into());
        }
    }
    o.insert("digits_verified".into(), verified.into());
    o.insert("error_bounds".into(), errs.into());
    o.insert(
        "notes".into(),
        a.notes
            .iter()
            .map(|n| Value::from(n.as_str()))
            .collect::<Vec<_>>()
            .into(),
    );
    let all = serde_json::to_string_pretty(&Value::Object(o)).unwrap_or_default() + "\n";
    // the rows go where their mark is, between "[" and "]"
    let mark = serde_json::to_string(ROWS_MARK).unwrap_or_default();
    match all.find(&mark) {
        Some(k) => {
            let close = if stats.is_some_and(|s| s.rows > 0) {
                "\n  ]"
            } else {
                "]"
            };
            (
                format!("{}[", &all[..k]),
                format!("{close}{}", &all[k + mark.len()..]),
            )
        }
        None => (all, String::new()),
    }
}

fn csv(a: &Answer) -> String {
    let mut out = String::new();
    if a.question == Question::Trajectory {
        out.push_str(&columns(a).join(","));
        out.push('\n');
        return out;
    }
    let rigorous = !a.proved.is_empty();
    out.push_str(if rigorous {
        "key,value,digits_verified,error_bound,digits_rigorous,mid,rad\n"
    } else {
        "key,value,digits_verified,error_bound\n"
    });
    let tail = if rigorous { ",,," } else { "" };
    let m = &a.model;
    // the model's coefficients as `model_mu_*`: `forces` answers the
    // friction each contact needs under the keys `mu_floor`, `mu_contact`
    for (k, v) in [
        ("model_mu_floor", m.floor().mu_text()),
        ("model_mu_contact", m.contact().mu_text()),
        ("branch", a.branch.name()),
    ] {
        // "S,K" (static, kinetic) holds a comma: quoted (RFC 4180)
        let v = if v.contains(',') {
            format!("\"{v}\"")
        } else {
            v.to_string()
        };
        out.push_str(&format!("{k},{v},,{tail}\n"));
    }
    if let Some(sm) = a.start_mode {
        out.push_str(&format!("start_mode,{},,{tail}\n", sm.tag()));
    }
    if let Some(p) = a.phase {
        out.push_str(&format!("mode,{},,{tail}\n", p.tag()));
    }
    if let Some(e) = a.end {
        out.push_str(&format!("end,\"{}\",,{tail}\n", e.name()));
    }
    for (i, e) in a.events.iter().enumerate() {
        let which = e
            .which
            .map(|w| format!("{}_", w.name()))
            .unwrap_or_default();
        for (what, v) in [("t", &e.t), ("theta", &e.theta)] {
            out.push_str(&format!(
                "event{}_{}_{}{},{},{},{}{tail}\n",
                i + 1,
                e.kind.name(),
                which,
                what,
                v.text,
                v.digits,
                v.err_text()
            ));
        }
        out.push_str(&format!(
            "event{}_mode,{},,{tail}\n",
            i + 1,
            e.phase.map_or_else(|| "end".to_string(), |p| p.tag())
        ));
        if !e.also.is_empty() {
            out.push_str(&format!(
                "event{}_alternatives,\"{}\",,{tail}\n",
                i + 1,
                e.also.join(" ")
            ));
        }
    }
    for (i, v) in a.values.iter().enumerate() {
        match a.proved.get(i).and_then(|p| p.as_ref()) {
            Some(pv) => {
                let (mid, rad) = pv.texts(a.digits);
                out.push_str(&format!(
                    "{},{},{},{},{},{},{}\n",
                    v.name,
                    pv.shown.text,
                    v.digits,
                    v.err_text(),
                    pv.shown.digits,
                    mid,
                    rad
                ));
            }
            None => out.push_str(&format!(
                "{},{},{},{}{tail}\n",
                v.name,
                v.text,
                v.digits,
                v.err_text()
            )),
        }
    }
    // the notes are findings too: one row each, the text quoted as CSV requires
    for n in &a.notes {
        out.push_str(&format!("note,\"{}\",,{tail}\n", n.replace('"', "\"\"")));
    }
    out
}

/// Per column, the cells printed 0 that are 0 only to within an absolute
/// bound: one sentence per such column, naming the largest bound.
fn zero_cells(stats: &RowStats) -> Vec<String> {
    let mut out = Vec::new();
    for (j, c) in stats.names.iter().enumerate() {
        if let Some((n, Some(w))) = stats.zeros.get(j) {
            out.push(format!(
                "{n} value(s) of {c} printed 0 are zero only to within an absolute bound, |{c}| <= {}",
                cylroll::numeric::decimal::short(w)
            ));
        }
    }
    out
}
