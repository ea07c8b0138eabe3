//! Command-line interface: parse, call the library, print. No physics here.

use clap::{Args, Parser, Subcommand, ValueEnum};
use cylroll::error::{Error, Result};
use cylroll::exact::{rational_text, Exact};
use cylroll::model::input::{self, FRICTION_KEYS, MODEL_KEYS};
use cylroll::model::Model;
use cylroll::motion::answer::VerifiedEvent;
use cylroll::motion::Friction;
use cylroll::numeric::verify::Verified;
use cylroll::oracle::rigorous::{enclosure_why, prove_with, stick_end_proved, Proved};
use cylroll::oracle::{Oracle, FORCE_KEYS, TRAJECTORY_COLUMNS};
use rug::Rational;
use std::io::Write;

#[derive(Parser, Debug)]
#[command(
    name = "cylroll",
    version,
    about = "Reference oracle for a cylinder rolling on a rolling cylinder: verified digits at any precision"
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Separation angle theta_s (N12 = 0), separation time, sign changes, friction findings
    Separation {
        #[command(flatten)]
        common: Common,
        /// Friction coefficient: report where rolling without slipping first fails
        #[arg(long, allow_hyphen_values = true)]
        mu: Option<String>,
    },
    /// Time from the start to the angle --to
    Time {
        #[command(flatten)]
        common: Common,
        /// Target angle (radians; e.g. 0.5, 1/3, pi/4)
        #[arg(long, allow_hyphen_values = true)]
        to: String,
    },
    /// Constraint forces, theta_dot, theta_ddot and the friction needed at angle --theta
    Forces {
        #[command(flatten)]
        common: Common,
        /// Angle (radians)
        #[arg(long, allow_hyphen_values = true)]
        theta: String,
    },
    /// Rows t, theta, theta_dot, theta_ddot, phi1, phi2, x1, x2, y2, F1, N1, F21, N12 (with friction also s1, s12, work, mode) at given times
    Trajectory {
        #[command(flatten)]
        common: Common,
        /// Comma-separated times
        #[arg(long, allow_hyphen_values = true, conflicts_with_all = ["t_end", "steps"])]
        times: Option<String>,
        /// Last time of an equally spaced grid (with --steps)
        #[arg(long, allow_hyphen_values = true, requires = "steps")]
        t_end: Option<String>,
        /// Number of intervals of the grid 0, t_end/N, ..., t_end (1 to 100000)
        #[arg(long, requires = "t_end", allow_hyphen_values = true, value_parser = steps_arg)]
        steps: Option<u32>,
    },
    /// Render every golden case (golden/cases/*.toml) into golden/data/<case>.json and .csv
    Golden {
        /// The golden directory
        #[arg(long, default_value = "golden")]
        dir: std::path::PathBuf,
    },
    /// Judge another program's CSV against the oracle (exit 1 if a tolerance is exceeded)
    Check {
        /// The candidate CSV (header row with golden column names; t required)
        candidate: std::path::PathBuf,
        /// The golden case it simulates (a file stem of golden/cases)
        #[arg(long)]
        case: String,
        /// Relative tolerance (>= 0)
        #[arg(long, default_value_t = 1e-8, allow_hyphen_values = true, value_parser = tol_arg)]
        rtol: f64,
        /// Absolute tolerance (>= 0)
        #[arg(long, default_value_t = 1e-10, allow_hyphen_values = true, value_parser = tol_arg)]
        atol: f64,
        /// Significant digits of the oracle values compared against, 1 to 2000
        #[arg(long, default_value_t = 20, allow_hyphen_values = true, value_parser = digits_arg)]
        digits: u32,
        /// Largest number of data rows accepted (the candidate is read in chunks, in bounded memory)
        #[arg(long, default_value_t = 1_000_000, allow_hyphen_values = true, value_parser = rows_arg)]
        max_rows: usize,
        /// The golden directory (case files in its cases/ folder)
        #[arg(long, default_value = "golden")]
        golden: std::path::PathBuf,
        /// Output format: text (a table), json or csv (one row per column)
        #[arg(long, value_enum, default_value_t = Format::Text)]
        format: Format,
    },
    /// Audit every formula of the paper against the first-principles mechanics (writes reports/audit.md)
    Audit {
        /// Audit only this equation (e.g. 23, 43, fn8)
        #[arg(long)]
        equation: Option<String>,
        /// Directory of the reports
        #[arg(long, default_value = "reports")]
        out: std::path::PathBuf,
    },
    /// The main job: figures and tables for the built-in cases, written to reports/
    Report {
        /// Directory of the reports
        #[arg(long, default_value = "reports")]
        out: std::path::PathBuf,
        /// No progress bars
        #[arg(long)]
        quiet: bool,
    },
    /// Run the second, independent route (time integration with Lagrange multipliers) against the first
    Verify {
        /// Significant digits to compare, 1 to 2000
        #[arg(long, default_value_t = 30, allow_hyphen_values = true, value_parser = digits_arg)]
        digits: u32,
        /// A stack of n cylinders instead (see README, "Stacks")
        #[arg(long)]
        stack: Option<String>,
        /// Output format (a stack: text or json)
        #[arg(long, value_enum, default_value_t = Format::Text)]
        format: Format,
        /// Print the wall-clock time of each case to standard error
        #[arg(long)]
        timings: bool,
    },
}

#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
pub enum Format {
    Text,
    Json,
    Csv,
}

/// Model flags and output options shared by every subcommand.
#[derive(Args, Debug, Clone)]
pub struct Common {
    /// TOML file with any of the model keys (flags override it)
    #[arg(long)]
    params: Option<std::path::PathBuf>,
    /// Floor under cylinder 1: roll | slip | fixed
    #[arg(long)]
    floor: Option<String>,
    /// Contact between the cylinders: roll | slip
    #[arg(long)]
    contact: Option<String>,
    /// Mass of the lower cylinder 1, > 0 [default: 1]
    #[arg(long, allow_hyphen_values = true)]
    m1: Option<String>,
    /// Mass of the upper cylinder 2, > 0 [default: 1]
    #[arg(long, allow_hyphen_values = true)]
    m2: Option<String>,
    /// Radius of cylinder 1, > 0 [default: 1]
    #[arg(long, allow_hyphen_values = true)]
    r1: Option<String>,
    /// Radius of cylinder 2, > 0 [default: 1]
    #[arg(long, allow_hyphen_values = true)]
    r2: Option<String>,
    /// I1 = k1 m1 r1^2; k1 >= 0 (1/2 solid, 1 thin shell, > 1 a bobbin) [default: 1/2]
    #[arg(long, allow_hyphen_values = true)]
    k1: Option<String>,
    /// I2 = k2 m2 r2^2; k2 >= 0 [default: 1/2]
    #[arg(long, allow_hyphen_values = true)]
    k2: Option<String>,
    /// Gravitational acceleration, > 0 [default: 1]
    #[arg(long, allow_hyphen_values = true)]
    g: Option<String>,
    /// Initial angle of the line of centres, clockwise from vertical (radians) [default: 0]
    #[arg(long, allow_hyphen_values = true)]
    theta0: Option<String>,
    /// Initial angular velocity of the line of centres [default: 0]
    #[arg(long, allow_hyphen_values = true)]
    thetadot0: Option<String>,
    /// Common rolling rate of the conserved momentum (phi1_dot when theta_dot = 0; paper eq. 17) [default: 0]
    #[arg(long, allow_hyphen_values = true)]
    omega0: Option<String>,
    /// Coulomb friction at the floor: inf (roll), a number >= 0, or S,K (static, kinetic)
    #[arg(long, allow_hyphen_values = true)]
    mu_floor: Option<String>,
    /// Coulomb friction between the cylinders: inf (roll), a number >= 0, or S,K
    #[arg(long, allow_hyphen_values = true)]
    mu_contact: Option<String>,
    /// Significant digits to verify and print, 1 to 2000
    #[arg(long, default_value_t = 30, allow_hyphen_values = true, value_parser = digits_arg)]
    digits: u32,
    /// Output format
    #[arg(long, value_enum, default_value_t = Format::Text)]
    format: Format,
    /// Prove the digits: interval enclosures [mid ± rad] with directed rounding (ideal models;
    /// see README, "Guarantees")
    #[arg(long)]
    rigorous: bool,
}

/// `--digits`: an integer 1..=MAX_DIGITS (a message clap prints on one line).
fn digits_arg(s: &str) -> std::result::Result<u32, String> {
    int_arg(s, 1, cylroll::oracle::MAX_DIGITS as u64).map(|v| v as u32)
}

/// An integer flag within `lo..=hi`.
fn int_arg(s: &str, lo: u64, hi: u64) -> std::result::Result<u64, String> {
    match s.trim().parse::<u64>() {
        Ok(v) if (lo..=hi).contains(&v) => Ok(v),
        _ => Err(format!("must be an integer between {lo} and {hi}")),
    }
}

/// `--steps`: 1..=100000 intervals.
fn steps_arg(s: &str) -> std::result::Result<u32, String> {
    int_arg(s, 1, 100_000).map(|v| v as u32)
}

/// `--max-rows`: 1..=10^8 rows.
fn rows_arg(s: &str) -> std::result::Result<usize, String> {
    int_arg(s, 1, 100_000_000).map(|v| v as usize)
}

/// A tolerance: a finite number >= 0.
fn tol_arg(s: &str) -> std::result::Result<f64, String> {
    match s.trim().parse::<f64>() {
        Ok(v) if v.is_finite() && v >= 0.0 => Ok(v),
        _ => Err("must be a finite number >= 0 (e.g. 1e-8)".into()),
    }
}

impl Common {
    fn flag(&self, key: &str) -> Option<String> {
        match key {
            "floor" => self.floor.clone(),
            "contact" => self.contact.clone(),
            "m1" => self.m1.clone(),
            "m2" => self.m2.clone(),
            "r1" => self.r1.clone(),
            "r2" => self.r2.clone(),
            "k1" => self.k1.clone(),
            "k2" => self.k2.clone(),
            "g" => self.g.clone(),
            "theta0" => self.theta0.clone(),
            "thetadot0" => self.thetadot0.clone(),
            "omega0" => self.omega0.clone(),
            "mu_floor" => self.mu_floor.clone(),
            "mu_contact" => self.mu_contact.clone(),
            _ => None,
        }
    }

    /// The key/value pairs from the defaults, then `--params`, then the flags.
    fn pairs(&self) -> Result<input::Pairs> {
        let mut vals = input::Pairs::new();
        if let Some(path) = &self.params {
            let table = input::read_toml(path, "params")?;
            vals = input::pairs_from_toml(&table, "params", &input::CASE_KEYS)?;
        }
        for k in MODEL_KEYS.iter().chain(FRICTION_KEYS.iter()) {
            if let Some(v) = self.flag(k) {
                vals.insert(k.to_string(), v);
            }
        }
        Ok(vals)
    }

    /// The model and its friction laws. With only ideal laws (`inf`, `0`)
    /// the model is the equal ideal one and the friction `None`.
    pub fn model_friction(&self) -> Result<(Model, Option<Friction>)> {
        // a start at the top is the ideal models' limit θ0 → 0+ and is
        // judged by the command that runs
        input::model_and_friction(&self.pairs()?)
    }
}

/// A finished answer: ordered (key, value) pairs plus notes, rendered by format.
struct Answer {
    command: &'static str,
    model: Model,
    digits: u32,
    values: Vec<Verified>,
    notes: Vec<String>,
    table: Option<(Vec<&'static str>, Vec<Vec<Verified>>)>,
    /// With friction: the friction laws (echoed) and the event list.
    friction: Option<(Friction, String, Vec<VerifiedEvent>)>,
    /// With `--rigorous`: the enclosure of each value (None: not enclosed).
    proved: Vec<Option<Proved>>,
    /// With `--rigorous`: the enclosures of the table's rows.
    proved_rows: Vec<Vec<Proved>>,
}

fn json_str(s: &str) -> String {
    serde_json::Value::String(s.to_string()).to_string()
}

impl Answer {
    fn render(mut self, format: Format) -> String {
        // a finding is stated once, however many routes reached it
        let mut seen = std::collections::HashSet::new();
        self.notes.retain(|n| seen.insert(n.clone()));
        let this = &self;
        match format {
            Format::Text => this.text(),
            Format::Json => this.json(),
            Format::Csv => this.csv(),
        }
    }

    fn text(&self) -> String {
        let mut out = String::new();
        out.push_str(&format!(
            "# cylroll {} — {}\n",
            self.command,
            self.model.describe()
        ));
        out.push_str(&format!("# {} significant digits requested; each value below is verified to the digits printed\n", self.digits));
        let w = self.values.iter().map(|v| v.name.len()).max().unwrap_or(0);
        if !self.proved.is_empty() {
            out.push_str("# --rigorous: each value shows the digits its interval enclosure proves (directed rounding)\n");
        }
        for (i, v) in self.values.iter().enumerate() {
            if let Some(pr) = self.proved.get(i) {
                let line = match pr {
                    Some(pv) => {
                        let (mid, rad) = pv.texts(self.digits);
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
            let note = if v.text.starts_with(">=") {
                "[a lower bound: the normal force is 0 to within its error bound]".to_string()
            } else if v.digits == 0 {
                format!("[indistinguishable from 0: |x| <= {}]", v.err_text())
            } else {
                format!("[{} digits; |err| <= {}]", v.digits, v.err_text())
            };
            out.push_str(&format!("{:w$} = {}  {}\n", v.name, v.text, note, w = w));
        }
        if let Some((fr, start, events)) = &self.friction {
            out.push_str(&format!(
                "# friction: mu_floor = {}, mu_contact = {}{}\n",
                fr.floor,
                fr.contact,
                if start.is_empty() {
                    String::new()
                } else {
                    format!("; start mode: {start}")
                }
            ));
            for (i, e) in events.iter().enumerate() {
                out.push_str(&format!(
                    "event {}: {}{} at t = {} [{} digits], theta = {} [{} digits]{}\n",
                    i + 1,
                    e.kind.name(),
                    e.which
                        .map(|w| format!(" ({})", w.name()))
                        .unwrap_or_default(),
                    e.t.text,
                    e.t.digits,
                    e.theta.text,
                    e.theta.digits,
                    e.mode
                        .as_ref()
                        .map(|m| format!(" -> {m}"))
                        .unwrap_or_default()
                ));
            }
        }
        if let Some((cols, rows)) = &self.table {
            out.push_str(&cols.join("\t"));
            out.push('\n');
            if self.proved_rows.is_empty() {
                for r in rows {
                    let line: Vec<&str> = r.iter().map(|v| v.text.as_str()).collect();
                    out.push_str(&line.join("\t"));
                    out.push('\n');
                }
            } else {
                for r in &self.proved_rows {
                    let line: Vec<&str> = r.iter().map(|v| v.shown.text.as_str()).collect();
                    out.push_str(&line.join("\t"));
                    out.push('\n');
                }
                let least = self
                    .proved_rows
                    .iter()
                    .flatten()
                    .filter(|v| v.shown.text != "0")
                    .map(|v| v.shown.digits)
                    .min()
                    .unwrap_or(self.digits);
                out.push_str(&format!(
                    "note: --rigorous: every cell shows the digits its interval enclosure proves (at least {least} significant digits)\n"
                ));
            }
            for z in zero_cells(cols, rows) {
                out.push_str(&format!("note: {z}\n"));
            }
        }
        for n in &self.notes {
            out.push_str(&format!("note: {n}\n"));
        }
        out
    }

    fn json(&self) -> String {
        let mut o = serde_json::Map::new();
        o.insert("command".into(), self.command.into());
        let mut m = serde_json::Map::new();
        for (k, v) in self.model.echo() {
            m.insert(k.into(), v.into());
        }
        o.insert("model".into(), m.into());
        o.insert("digits_requested".into(), self.digits.to_string().into());
        if let Some((fr, start, events)) = &self.friction {
            o.insert("mu_floor".into(), fr.floor.to_string().into());
            o.insert("mu_contact".into(), fr.contact.to_string().into());
            if !start.is_empty() {
                o.insert("start_mode".into(), start.clone().into());
            }
            let evs: Vec<serde_json::Value> = events
                .iter()
                .map(|e| {
                    serde_json::json!({
                        "kind": e.kind.name(),
                        "contact": e.which.map(|w| w.name()),
                        "mode": e.mode,
                        "t": e.t.text,
                        "theta": e.theta.text,
                        "digits_verified": {"t": e.t.digits.to_string(), "theta": e.theta.digits.to_string()},
                        "error_bounds": {"t": e.t.err_text(), "theta": e.theta.err_text()},
                    })
                })
                .collect();
            o.insert("events".into(), evs.into());
        }
        let mut verified = serde_json::Map::new();
        let mut errs = serde_json::Map::new();
        let mut rig = serde_json::Map::new();
        let mut encl = serde_json::Map::new();
        let mut lower = serde_json::Map::new();
        for (i, v) in self.values.iter().enumerate() {
            match self.proved.get(i) {
                Some(Some(pv)) => {
                    o.insert(v.name.clone(), pv.shown.text.clone().into());
                    rig.insert(v.name.clone(), pv.shown.digits.to_string().into());
                    encl.insert(v.name.clone(), enclosure_json(pv, self.digits));
                }
                Some(None) => {
                    o.insert(v.name.clone(), v.text.clone().into());
                    rig.insert(v.name.clone(), serde_json::Value::Null);
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
            // values known only from below (text ">=X"): the number X, typed
            o.insert("lower_bounds".into(), lower.into());
        }
        if let Some((cols, rows)) = &self.table {
            o.insert(
                "columns".into(),
                cols.iter()
                    .map(|c| serde_json::Value::from(*c))
                    .collect::<Vec<_>>()
                    .into(),
            );
            // per column: the fewest digits verified in any row and the
            // largest error bound; a cell printed 0 is 0 only to within an
            // absolute bound, which its row states under "zero_within"
            let mut col_digits: Vec<Option<u32>> = vec![None; cols.len()];
            let mut col_err: Vec<Option<rug::Float>> = vec![None; cols.len()];
            let rows_json: Vec<serde_json::Value> = rows
                .iter()
                .map(|r| {
                    let mut row = serde_json::Map::new();
                    let mut zeros = serde_json::Map::new();
                    for (j, v) in r.iter().enumerate() {
                        row.insert(v.name.clone(), v.text.clone().into());
                        if v.name == "mode" {
                            continue;
                        }
                        if v.digits > 0 {
                            col_digits[j] =
                                Some(col_digits[j].map_or(v.digits, |d| d.min(v.digits)));
                        } else if v.text == "0" && !v.err_bound.is_zero() {
                            zeros.insert(v.name.clone(), v.err_text().into());
                        }
                        if col_err[j].as_ref().is_none_or(|e| v.err_bound > *e) {
                            col_err[j] = Some(v.err_bound.clone());
                        }
                    }
                    if !zeros.is_empty() {
                        row.insert("zero_within".into(), zeros.into());
                    }
                    row.into()
                })
                .collect();
            o.insert("rows".into(), rows_json.into());
            for (j, c) in cols.iter().enumerate() {
                if *c == "mode" {
                    continue;
                }
                verified.insert(
                    c.to_string(),
                    col_digits[j]
                        .map_or("0".to_string(), |d| d.to_string())
                        .into(),
                );
                if let Some(e) = &col_err[j] {
                    errs.insert(c.to_string(), cylroll::numeric::decimal::short(e).into());
                }
            }
        }
        if !self.proved_rows.is_empty() {
            let rows_json: Vec<serde_json::Value> = self
                .proved_rows
                .iter()
                .map(|r| {
                    let mut row = serde_json::Map::new();
                    let mut e = serde_json::Map::new();
                    for v in r {
                        row.insert(v.name.clone(), v.shown.text.clone().into());
                        e.insert(v.name.clone(), enclosure_json(v, self.digits));
                    }
                    row.insert("enclosures".into(), e.into());
                    row.into()
                })
                .collect();
            o.insert("rows".into(), rows_json.into());
            if let Some(first) = self.proved_rows.first() {
                for (j, v) in first.iter().enumerate() {
                    let d = self
                        .proved_rows
                        .iter()
                        .map(|r| r[j].shown.digits)
                        .min()
                        .unwrap_or(0);
                    rig.insert(v.name.clone(), d.to_string().into());
                }
            }
        }
        if !self.proved.is_empty() || !self.proved_rows.is_empty() {
            o.insert("digits_rigorous".into(), rig.into());
            if !encl.is_empty() {
                o.insert("enclosures".into(), encl.into());
            }
        }
        o.insert("digits_verified".into(), verified.into());
        o.insert("error_bounds".into(), errs.into());
        o.insert(
            "notes".into(),
            self.notes
                .iter()
                .map(|n| serde_json::Value::from(n.as_str()))
                .collect::<Vec<_>>()
                .into(),
        );
        let _ = json_str;
        serde_json::to_string_pretty(&serde_json::Value::Object(o)).expect("serializable") + "\n"
    }

    fn csv(&self) -> String {
        let mut out = String::new();
        if let (Some((cols, _)), false) = (&self.table, self.proved_rows.is_empty()) {
            out.push_str(&cols.join(","));
            out.push('\n');
            for r in &self.proved_rows {
                let line: Vec<&str> = r.iter().map(|v| v.shown.text.as_str()).collect();
                out.push_str(&line.join(","));
                out.push('\n');
            }
        } else if let Some((cols, rows)) = &self.table {
            out.push_str(&cols.join(","));
            out.push('\n');
            for r in rows {
                let line: Vec<&str> = r.iter().map(|v| v.text.as_str()).collect();
                out.push_str(&line.join(","));
                out.push('\n');
            }
        } else {
            out.push_str("key,value,digits_verified,error_bound\n");
            if let Some((_, _, events)) = &self.friction {
                for (i, e) in events.iter().enumerate() {
                    for (what, v) in [("t", &e.t), ("theta", &e.theta)] {
                        out.push_str(&format!(
                            "event{}_{}_{}{},{},{},{}\n",
                            i + 1,
                            e.kind.name(),
                            e.which
                                .map(|w| format!("{}_", w.name()))
                                .unwrap_or_default(),
                            what,
                            v.text,
                            v.digits,
                            v.err_text()
                        ));
                    }
                }
            }
            if self.proved.is_empty() {
                for v in &self.values {
                    out.push_str(&format!(
                        "{},{},{},{}\n",
                        v.name,
                        v.text,
                        v.digits,
                        v.err_text()
                    ));
                }
            } else {
                // with --rigorous: the proved digits, then the enclosure
                out = out.replace(
                    "key,value,digits_verified,error_bound\n",
                    "key,value,digits_verified,error_bound,digits_rigorous,mid,rad\n",
                );
                for (i, v) in self.values.iter().enumerate() {
                    match self.proved.get(i).and_then(|p| p.as_ref()) {
                        Some(pv) => {
                            let (mid, rad) = pv.texts(self.digits);
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
                            "{},{},{},{},,,\n",
                            v.name,
                            v.text,
                            v.digits,
                            v.err_text()
                        )),
                    }
                }
            }
            // the notes are findings too (e.g. "t_s is infinite"): one row
            // each, the text quoted as CSV requires
            for n in &self.notes {
                out.push_str(&format!("note,\"{}\",,\n", n.replace('"', "\"\"")));
            }
        }
        out
    }
}

/// `{"mid": …, "rad": …}` of an enclosure (decimal strings; mid with five
/// digits beyond those asked, rad rounded up).
fn enclosure_json(pv: &Proved, digits: u32) -> serde_json::Value {
    let (mid, rad) = pv.texts(digits);
    serde_json::json!({"mid": mid, "rad": rad})
}

/// Per column, the cells printed 0 that are 0 only to within an absolute
/// bound: one sentence per such column, naming the largest bound.
fn zero_cells(cols: &[&str], rows: &[Vec<Verified>]) -> Vec<String> {
    let mut out = Vec::new();
    for (j, c) in cols.iter().enumerate() {
        let mut n = 0;
        let mut worst: Option<&rug::Float> = None;
        for r in rows {
            let v = &r[j];
            if v.name != "mode" && v.text == "0" && !v.err_bound.is_zero() {
                n += 1;
                if worst.is_none_or(|w| v.err_bound > *w) {
                    worst = Some(&v.err_bound);
                }
            }
        }
        if let Some(w) = worst {
            out.push(format!(
                "{n} value(s) of {c} printed 0 are zero only to within an absolute bound, |{c}| <= {}",
                cylroll::numeric::decimal::short(w)
            ));
        }
    }
    out
}

fn proves_less(v: &[Proved], digits: u32) -> bool {
    v.iter()
        .any(|x| x.shown.digits < digits && x.shown.text != "0")
}

/// `--rigorous` is for the ideal models only.
fn rigorous_supported(common: &Common, friction: bool) -> Result<()> {
    if common.rigorous && friction {
        return Err(cylroll::oracle::rigorous::unsupported("with friction"));
    }
    Ok(())
}

fn parse_list(name: &str, s: &str) -> Result<Vec<Exact>> {
    s.split(',').map(|t| Exact::parse(name, t, false)).collect()
}

/// Runs the command and returns the text to print on standard output.
pub fn run(cli: Cli) -> Result<(String, i32)> {
    let (common, answer) = match cli.command {
        Command::Golden { dir } => return cylroll::golden::write_all(&dir).map(|s| (s, 0)),
        Command::Check {
            candidate,
            case,
            rtol,
            atol,
            digits,
            max_rows,
            golden,
            format,
        } => {
            let case = cylroll::golden::find_case(&golden, &case)?;
            let source = candidate.display().to_string();
            let file = std::fs::File::open(&candidate).map_err(|e| {
                Error::invalid("candidate", &source, format!("cannot be read: {e}"))
            })?;
            let lim = cylroll::check::Limits {
                rtol,
                atol,
                digits,
                max_rows,
            };
            let rep =
                cylroll::check::check_reader(std::io::BufReader::new(file), &source, &case, &lim)?;
            let out = match format {
                Format::Json => rep.json(),
                Format::Csv => rep.csv(),
                Format::Text => rep.text(),
            };
            return Ok((out, if rep.passed() { 0 } else { 1 }));
        }
        Command::Audit { equation, out } => {
            return cylroll::audit::run(equation.as_deref(), &out).map(|s| (s, 0))
        }
        Command::Report { out, quiet } => {
            return cylroll::report::run(&out, !quiet).map(|s| (s, 0))
        }
        Command::Verify {
            digits,
            stack,
            format,
            timings,
        } => {
            if let Some(spec) = stack {
                if format == Format::Csv {
                    return Err(Error::invalid(
                        "format",
                        "csv",
                        "verify --stack prints text or json",
                    ));
                }
                return cylroll::stack::stack_report(&spec, digits, format == Format::Json)
                    .map(|s| (s, 0));
            }
            let rep = cylroll::crosscheck::verify_report(digits)?;
            if timings {
                eprint!("{}", rep.timings());
            }
            let out = match format {
                Format::Text => rep.text(),
                Format::Json => rep.json(),
                Format::Csv => rep.csv(),
            };
            return Ok((out, 0));
        }
        Command::Separation { common, mu } => {
            let (model, fr) = common.model_friction()?;
            // with friction, --rigorous encloses the first slip onset only
            if let Some(fr) = fr {
                if let Some(m) = mu {
                    return Err(Error::invalid(
                        "mu",
                        m,
                        "is the ideal-rolling diagnostic; with --mu-floor/--mu-contact the slip \
                         itself is computed (see the events)",
                    ));
                }
                let ans = cylroll::motion::answer::separation(&model, &fr, common.digits)?;
                let mut values = ans.values.clone();
                let mut proved = Vec::new();
                let mut notes = ans.notes.clone();
                notes.insert(
                    0,
                    format!("the first impact is on the {}", ans.impact_surface),
                );
                if common.rigorous {
                    match stick_end_proved(&model, &fr, &ans, common.digits) {
                        Ok(slots) => {
                            proved.resize(values.len(), None);
                            let mut names = Vec::new();
                            for (at, v, pv) in slots {
                                if pv.is_none() {
                                    notes.push(format!(
                                        "{} is not enclosed: verified digits only",
                                        v.name
                                    ));
                                } else {
                                    names.push(v.name.clone());
                                }
                                match at {
                                    Some(i) => proved[i] = pv,
                                    None => {
                                        values.push(v);
                                        proved.push(pv);
                                    }
                                }
                            }
                            if !names.is_empty() {
                                notes.push(format!(
                                    "--rigorous encloses {}: where sticking ends, a root of a \
                                 polynomial in cos theta while both contacts stick (the rolling \
                                 model's closed forms), and the time to it; the phases after it \
                                 are integrated and verified only",
                                    names.join(" and ")
                                ));
                            }
                        }
                        Err(why) => notes.push(format!(
                            "--rigorous: nothing is enclosed ({why}); every value is verified only"
                        )),
                    }
                }
                let a = Answer {
                    command: "separation",
                    model,
                    digits: common.digits,
                    values,
                    notes,
                    table: None,
                    friction: Some((fr, ans.start_mode, ans.events)),
                    proved,
                    proved_rows: Vec::new(),
                };
                return Ok((a.render(common.format), 0));
            }
            let mu = mu.map(|s| Exact::parse("mu", &s, false)).transpose()?;
            let mut o = Oracle::new(&model, common.digits)?.with_mu(mu)?;
            let sep = o.separation()?;
            let has_ts = sep.t_s.is_some();
            let mut values = vec![sep.theta_s];
            values.extend(sep.t_s);
            values.extend(sep.extra);
            let mut notes = sep.notes;
            let mut proved = Vec::new();
            if common.rigorous {
                let digits = common.digits;
                let (th, ts) = match prove_with(
                    digits,
                    |p| o.rigorous_separation(p),
                    |(th, ts)| {
                        th.shown.digits < digits
                            || ts.as_ref().is_ok_and(|t| t.shown.digits < digits)
                    },
                ) {
                    Ok((th, ts)) => (Some(th), ts),
                    Err(e) => {
                        let why = enclosure_why(&e);
                        notes.push(format!(
                            "theta_s is not enclosed ({why}): verified digits only"
                        ));
                        (None, Err(why))
                    }
                };
                proved.push(th);
                if has_ts {
                    match ts {
                        Ok(t) => proved.push(Some(t)),
                        Err(why) => {
                            notes
                                .push(format!("t_s is not enclosed ({why}): verified digits only"));
                            proved.push(None);
                        }
                    }
                }
                proved.resize(values.len(), None);
                notes.push(
                    "--rigorous encloses theta_s and t_s; the other findings are verified only"
                        .into(),
                );
            }
            let a = Answer {
                command: "separation",
                model,
                digits: common.digits,
                values,
                notes,
                table: None,
                friction: None,
                proved,
                proved_rows: Vec::new(),
            };
            (common, a)
        }
        Command::Time { common, to } => {
            let (model, fr) = common.model_friction()?;
            rigorous_supported(&common, fr.is_some())?;
            let theta = Exact::parse("to", &to, true)?;
            if let Some(fr) = fr {
                let (t, mode) =
                    cylroll::motion::answer::time_at(&model, &fr, common.digits, &theta)?;
                let a = Answer {
                    command: "time",
                    model,
                    digits: common.digits,
                    values: vec![t],
                    notes: vec![format!("mode at theta: {mode}")],
                    table: None,
                    friction: Some((fr, String::new(), vec![])),
                    proved: Vec::new(),
                    proved_rows: Vec::new(),
                };
                return Ok((a.render(common.format), 0));
            }
            rigorous_supported(&common, false)?;
            let mut o = Oracle::new(&model, common.digits)?;
            let t = o.time_at(&theta)?;
            let mut proved = Vec::new();
            let mut notes = vec![];
            if common.rigorous {
                let digits = common.digits;
                match prove_with(
                    digits,
                    |p| o.rigorous_time(&theta, p),
                    |v| v.shown.digits < digits,
                ) {
                    Ok(pv) => proved.push(Some(pv)),
                    Err(e) => {
                        proved.push(None);
                        notes.push(format!(
                            "t is not enclosed ({}): verified digits only",
                            enclosure_why(&e)
                        ));
                    }
                }
            }
            let a = Answer {
                command: "time",
                model,
                digits: common.digits,
                values: vec![t],
                notes,
                table: None,
                friction: None,
                proved,
                proved_rows: Vec::new(),
            };
            (common, a)
        }
        Command::Forces { common, theta } => {
            let (model, fr) = common.model_friction()?;
            rigorous_supported(&common, fr.is_some())?;
            let th = Exact::parse("theta", &theta, true)?;
            if let Some(fr) = fr {
                let (values, mode) =
                    cylroll::motion::answer::forces_at(&model, &fr, common.digits, &th)?;
                let a = Answer {
                    command: "forces",
                    model,
                    digits: common.digits,
                    values,
                    notes: vec![format!(
                        "the state where theta first reaches {theta}; mode there: {mode}"
                    )],
                    table: None,
                    friction: Some((fr, String::new(), vec![])),
                    proved: Vec::new(),
                    proved_rows: Vec::new(),
                };
                return Ok((a.render(common.format), 0));
            }
            let mut o = Oracle::new(&model, common.digits)?;
            let mut values = o.forces_at(&th)?;
            debug_assert_eq!(values.len(), FORCE_KEYS.len());
            // the most friction needed so far, and where
            values.extend(o.friction_needed(&th)?);
            let mut proved: Vec<Option<Proved>> = Vec::new();
            let mut rig_notes: Vec<String> = Vec::new();
            if common.rigorous {
                let digits = common.digits;
                match prove_with(
                    digits,
                    |p| o.rigorous_forces(&th, p),
                    |v| {
                        v.iter().any(|x| {
                            x.as_ref()
                                .is_some_and(|x| x.shown.digits < digits && x.shown.text != "0")
                        })
                    },
                ) {
                    Ok(pv) => proved = pv,
                    Err(e) => rig_notes.push(format!(
                        "the forces are not enclosed ({}): verified digits only",
                        enclosure_why(&e)
                    )),
                }
                proved.resize(values.len(), None);
            }
            let mut notes = rig_notes;
            for v in values.iter().filter(|v| v.text.starts_with(">=")) {
                notes.push(format!(
                    "{} has no finite verified value here: the normal force is 0 to within its \
                     error bound (theta is theta_s to the accuracy of the computation), so only \
                     the lower bound |F|/bound(N) is given",
                    v.name
                ));
            }
            let a = Answer {
                command: "forces",
                model,
                digits: common.digits,
                values,
                notes,
                table: None,
                friction: None,
                proved,
                proved_rows: Vec::new(),
            };
            (common, a)
        }
        Command::Trajectory {
            common,
            times,
            t_end,
            steps,
        } => {
            let times = match (times, t_end, steps) {
                (Some(list), _, _) => parse_list("times", &list)?,
                (None, Some(te), Some(n)) => {
                    if n == 0 || n > 100_000 {
                        return Err(Error::invalid("steps", n, "must be between 1 and 100000"));
                    }
                    let te = Exact::parse("t-end", &te, false)?;
                    if te.signum() <= 0 {
                        return Err(Error::invalid("t-end", &te, "must be > 0"));
                    }
                    (0..=n)
                        .map(|i| Exact::rational(&te.coef * Rational::from((i, n))))
                        .collect()
                }
                _ => {
                    return Err(Error::invalid(
                        "times",
                        "",
                        "give --times t1,t2,... or --t-end T --steps N",
                    ))
                }
            };
            let (model, fr) = common.model_friction()?;
            rigorous_supported(&common, fr.is_some())?;
            if let Some(fr) = fr {
                let ans = cylroll::motion::answer::trajectory(&model, &fr, common.digits, &times)?;
                let p = ans.rows.first().map_or(64, |r| r[0].value.prec());
                let rows = ans
                    .rows
                    .into_iter()
                    .zip(ans.modes)
                    .map(|(mut r, m)| {
                        r.push(Verified {
                            name: "mode".into(),
                            value: rug::Float::new(p),
                            text: m,
                            digits: 0,
                            err_bound: rug::Float::new(p),
                            precs: (p, p),
                        });
                        r
                    })
                    .collect();
                let mut cols = cylroll::motion::columns();
                cols.push("mode");
                let a = Answer {
                    command: "trajectory",
                    model,
                    digits: common.digits,
                    values: vec![],
                    notes: vec![],
                    table: Some((cols, rows)),
                    friction: Some((fr, String::new(), vec![])),
                    proved: Vec::new(),
                    proved_rows: Vec::new(),
                };
                return Ok((a.render(common.format), 0));
            }
            rigorous_supported(&common, false)?;
            let mut o = Oracle::new(&model, common.digits)?;
            let rows = o.trajectory(&times)?;
            let mut proved_rows = Vec::new();
            let mut notes = vec![];
            if common.rigorous {
                let digits = common.digits;
                for t in &times {
                    match prove_with(digits, |p| o.rigorous_row(t, p), |v| proves_less(v, digits)) {
                        Ok(r) => proved_rows.push(r),
                        Err(e) => {
                            proved_rows.clear();
                            notes.push(format!(
                                "the rows are not enclosed (t = {t}: {}): verified digits only",
                                enclosure_why(&e)
                            ));
                            break;
                        }
                    }
                }
            }
            let a = Answer {
                command: "trajectory",
                model,
                digits: common.digits,
                values: vec![],
                notes,
                table: Some((TRAJECTORY_COLUMNS.to_vec(), rows)),
                friction: None,
                proved: Vec::new(),
                proved_rows,
            };
            (common, a)
        }
    };
    let _ = rational_text;
    Ok((answer.render(common.format), 0))
}

/// Entry point used by `main`: prints or reports the error, returns the exit code.
pub fn main_with(args: Vec<String>) -> i32 {
    let cli = match Cli::try_parse_from(args) {
        Ok(c) => c,
        Err(e) => {
            if !e.use_stderr() {
                // --help, --version
                let _ = e.print();
                return 0;
            }
            eprintln!("error: {}", one_line(&e.render().to_string()));
            return 2;
        }
    };
    match run(cli) {
        Ok((out, code)) => {
            let mut so = std::io::stdout().lock();
            if let Err(e) = so.write_all(out.as_bytes()).and_then(|_| so.flush()) {
                eprintln!("error: cannot write standard output: {e}");
                return 4;
            }
            code
        }
        Err(e) => {
            eprintln!("error: {}", one_line(&e.to_string()));
            e.exit_code()
        }
    }
}

/// A message on one line: clap's multi-line errors (tip, usage) joined, the
/// usage block dropped, long given values shortened.
fn one_line(msg: &str) -> String {
    let mut parts: Vec<String> = Vec::new();
    for line in msg.lines() {
        let l = line.trim();
        if l.starts_with("Usage:") || l.starts_with("For more information") {
            break;
        }
        if !l.is_empty() {
            parts.push(l.trim_start_matches("tip: ").to_string());
        }
    }
    let mut s = String::new();
    for p in &parts {
        if !s.is_empty() {
            s.push_str(if s.ends_with(':') { " " } else { "; " });
        }
        s.push_str(p);
    }
    if let Some(rest) = s.strip_prefix("error: ") {
        s = rest.to_string();
    }
    // a value clap echoes is not shortened by the library: cut the line
    const MAX: usize = 400;
    if s.chars().count() > MAX {
        s = s.chars().take(MAX).collect::<String>() + "...";
    }
    if msg.contains("For more information") {
        s.push_str(" (see --help)");
    }
    s
}
