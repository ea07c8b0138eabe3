//! Command-line interface: parse, call the library, print. No physics here.

use clap::{Args, Parser, Subcommand, ValueEnum};
use cylroll::error::{Error, Result};
use cylroll::exact::{rational_text, Exact};
use cylroll::friction::answer::VerifiedEvent;
use cylroll::friction::Friction;
use cylroll::input::{self, FRICTION_KEYS, MODEL_KEYS};
use cylroll::model::Model;
use cylroll::numeric::verify::Verified;
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
    /// Rows t, theta, theta_dot, phi1, phi2, x1, x2, y2, F1, N1, F21, N12 at given times
    Trajectory {
        #[command(flatten)]
        common: Common,
        /// Comma-separated times
        #[arg(long, allow_hyphen_values = true, conflicts_with_all = ["t_end", "steps"])]
        times: Option<String>,
        /// Last time of an equally spaced grid (with --steps)
        #[arg(long, allow_hyphen_values = true, requires = "steps")]
        t_end: Option<String>,
        /// Number of intervals of the grid 0, t_end/N, ..., t_end
        #[arg(long, requires = "t_end")]
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
        /// Relative tolerance
        #[arg(long, default_value_t = 1e-8)]
        rtol: f64,
        /// Absolute tolerance
        #[arg(long, default_value_t = 1e-10)]
        atol: f64,
        /// Significant digits of the oracle values compared against
        #[arg(long, default_value_t = 20)]
        digits: u32,
        /// The golden directory
        #[arg(long, default_value = "golden")]
        golden: std::path::PathBuf,
        /// Output format (text or json)
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
        /// Significant digits to compare
        #[arg(long, default_value_t = 30)]
        digits: u32,
        /// A stack of n cylinders instead (see README, "Stacks")
        #[arg(long)]
        stack: Option<String>,
        /// Output format
        #[arg(long, value_enum, default_value_t = Format::Text)]
        format: Format,
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
    #[arg(long, allow_hyphen_values = true)]
    m1: Option<String>,
    #[arg(long, allow_hyphen_values = true)]
    m2: Option<String>,
    #[arg(long, allow_hyphen_values = true)]
    r1: Option<String>,
    #[arg(long, allow_hyphen_values = true)]
    r2: Option<String>,
    /// I1 = k1 m1 r1^2
    #[arg(long, allow_hyphen_values = true)]
    k1: Option<String>,
    /// I2 = k2 m2 r2^2
    #[arg(long, allow_hyphen_values = true)]
    k2: Option<String>,
    #[arg(long, allow_hyphen_values = true)]
    g: Option<String>,
    /// Initial angle of the line of centres, clockwise from vertical (radians)
    #[arg(long, allow_hyphen_values = true)]
    theta0: Option<String>,
    /// Initial angular velocity of the line of centres
    #[arg(long, allow_hyphen_values = true)]
    thetadot0: Option<String>,
    /// Common rolling rate of the conserved momentum (phi1_dot when theta_dot = 0; paper eq. 17)
    #[arg(long, allow_hyphen_values = true)]
    omega0: Option<String>,
    /// Coulomb friction at the floor: inf (roll), a number >= 0, or S,K (static, kinetic)
    #[arg(long, allow_hyphen_values = true)]
    mu_floor: Option<String>,
    /// Coulomb friction between the cylinders: inf (roll), a number >= 0, or S,K
    #[arg(long, allow_hyphen_values = true)]
    mu_contact: Option<String>,
    /// Significant digits to verify and print
    #[arg(long, default_value_t = 30)]
    digits: u32,
    /// Output format
    #[arg(long, value_enum, default_value_t = Format::Text)]
    format: Format,
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
            vals = input::pairs_from_toml(&table, "params", &[])?;
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
        let vals = self.pairs()?;
        let model = input::model_from_pairs(&vals)?;
        let fr = input::friction_for(&vals, &model)?;
        // the laws must fit the model; a start at the top is the ideal
        // models' limit θ0 → 0+ and is judged by the command that runs
        cylroll::friction::check_laws(&model, &fr)?;
        let eff = cylroll::friction::effective_model(&model, &fr)?;
        if fr.floor.is_coulomb() || fr.contact.is_coulomb() {
            Ok((eff, Some(fr)))
        } else {
            Ok((eff, None))
        }
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
}

fn json_str(s: &str) -> String {
    serde_json::Value::String(s.to_string()).to_string()
}

impl Answer {
    fn render(&self, format: Format) -> String {
        match format {
            Format::Text => self.text(),
            Format::Json => self.json(),
            Format::Csv => self.csv(),
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
        for v in &self.values {
            let note = if v.digits == 0 {
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
            for r in rows {
                let line: Vec<&str> = r.iter().map(|v| v.text.as_str()).collect();
                out.push_str(&line.join("\t"));
                out.push('\n');
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
        for v in &self.values {
            o.insert(v.name.clone(), v.text.clone().into());
            verified.insert(v.name.clone(), v.digits.to_string().into());
            errs.insert(v.name.clone(), v.err_text().into());
        }
        if let Some((cols, rows)) = &self.table {
            o.insert(
                "columns".into(),
                cols.iter()
                    .map(|c| serde_json::Value::from(*c))
                    .collect::<Vec<_>>()
                    .into(),
            );
            let mut min_digits = self.digits;
            let rows_json: Vec<serde_json::Value> = rows
                .iter()
                .map(|r| {
                    let mut row = serde_json::Map::new();
                    for v in r {
                        if v.digits > 0 {
                            min_digits = min_digits.min(v.digits);
                        }
                        row.insert(v.name.clone(), v.text.clone().into());
                    }
                    row.into()
                })
                .collect();
            o.insert("rows".into(), rows_json.into());
            verified.insert("rows".into(), min_digits.to_string().into());
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
        if let Some((cols, rows)) = &self.table {
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
            for v in &self.values {
                out.push_str(&format!(
                    "{},{},{},{}\n",
                    v.name,
                    v.text,
                    v.digits,
                    v.err_text()
                ));
            }
        }
        out
    }
}

fn parse_list(name: &str, s: &str) -> Result<Vec<Exact>> {
    s.split(',').map(|t| Exact::parse(name, t, false)).collect()
}

/// Runs the command and returns the text to print on standard output.
pub fn run(cli: Cli) -> Result<(String, i32)> {
    let (common, answer) = match cli.command {
        Command::Golden { dir } => return cylroll::record::write_all(&dir).map(|s| (s, 0)),
        Command::Check {
            candidate,
            case,
            rtol,
            atol,
            digits,
            golden,
            format,
        } => {
            let text = std::fs::read_to_string(&candidate).map_err(|e| Error::Io {
                path: candidate.display().to_string(),
                what: e.to_string(),
            })?;
            let case = cylroll::record::find_case(&golden, &case)?;
            let rep = cylroll::record::check::check(
                &text,
                &candidate.display().to_string(),
                &case,
                rtol,
                atol,
                digits,
            )?;
            let out = if format == Format::Json {
                rep.json()
            } else {
                rep.text()
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
        } => {
            return match stack {
                Some(spec) => cylroll::dae::stack_report(&spec, digits, format == Format::Json),
                None => cylroll::dae::verify_report(digits),
            }
            .map(|s| (s, 0))
        }
        Command::Separation { common, mu } => {
            let (model, fr) = common.model_friction()?;
            if let Some(fr) = fr {
                if let Some(m) = mu {
                    return Err(Error::invalid(
                        "mu",
                        m,
                        "is the ideal-rolling diagnostic; with --mu-floor/--mu-contact the slip \
                         itself is computed (see the events)",
                    ));
                }
                let ans = cylroll::friction::answer::separation(&model, &fr, common.digits)?;
                let mut notes = ans.notes;
                notes.insert(
                    0,
                    format!("the first impact is on the {}", ans.impact_surface),
                );
                let a = Answer {
                    command: "separation",
                    model,
                    digits: common.digits,
                    values: ans.values,
                    notes,
                    table: None,
                    friction: Some((fr, ans.start_mode, ans.events)),
                };
                return Ok((a.render(common.format), 0));
            }
            let mu = mu.map(|s| Exact::parse("mu", &s, false)).transpose()?;
            let mut o = Oracle::new(&model, common.digits)?.with_mu(mu)?;
            let sep = o.separation()?;
            let mut values = vec![sep.theta_s];
            values.extend(sep.t_s);
            values.extend(sep.extra);
            let a = Answer {
                command: "separation",
                model,
                digits: common.digits,
                values,
                notes: sep.notes,
                table: None,
                friction: None,
            };
            (common, a)
        }
        Command::Time { common, to } => {
            let (model, fr) = common.model_friction()?;
            let theta = Exact::parse("to", &to, true)?;
            if let Some(fr) = fr {
                let (t, mode) =
                    cylroll::friction::answer::time_at(&model, &fr, common.digits, &theta)?;
                let a = Answer {
                    command: "time",
                    model,
                    digits: common.digits,
                    values: vec![t],
                    notes: vec![format!("mode at theta: {mode}")],
                    table: None,
                    friction: Some((fr, String::new(), vec![])),
                };
                return Ok((a.render(common.format), 0));
            }
            let mut o = Oracle::new(&model, common.digits)?;
            let t = o.time_at(&theta)?;
            let a = Answer {
                command: "time",
                model,
                digits: common.digits,
                values: vec![t],
                notes: vec![],
                table: None,
                friction: None,
            };
            (common, a)
        }
        Command::Forces { common, theta } => {
            let (model, fr) = common.model_friction()?;
            let th = Exact::parse("theta", &theta, true)?;
            if let Some(fr) = fr {
                let (values, mode) =
                    cylroll::friction::answer::forces_at(&model, &fr, common.digits, &th)?;
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
                };
                return Ok((a.render(common.format), 0));
            }
            let mut o = Oracle::new(&model, common.digits)?;
            let values = o.forces_at(&th)?;
            debug_assert_eq!(values.len(), FORCE_KEYS.len());
            let a = Answer {
                command: "forces",
                model,
                digits: common.digits,
                values,
                notes: vec![],
                table: None,
                friction: None,
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
            if let Some(fr) = fr {
                let ans =
                    cylroll::friction::answer::trajectory(&model, &fr, common.digits, &times)?;
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
                let mut cols = cylroll::friction::columns();
                cols.push("mode");
                let a = Answer {
                    command: "trajectory",
                    model,
                    digits: common.digits,
                    values: vec![],
                    notes: vec![],
                    table: Some((cols, rows)),
                    friction: Some((fr, String::new(), vec![])),
                };
                return Ok((a.render(common.format), 0));
            }
            let mut o = Oracle::new(&model, common.digits)?;
            let rows = o.trajectory(&times)?;
            let a = Answer {
                command: "trajectory",
                model,
                digits: common.digits,
                values: vec![],
                notes: vec![],
                table: Some((TRAJECTORY_COLUMNS.to_vec(), rows)),
                friction: None,
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
            let code = if e.use_stderr() { 2 } else { 0 };
            let _ = e.print();
            return code;
        }
    };
    match run(cli) {
        Ok((out, code)) => {
            let mut so = std::io::stdout().lock();
            if so.write_all(out.as_bytes()).is_err() {
                return 4;
            }
            code
        }
        Err(e) => {
            eprintln!("error: {e}");
            e.exit_code()
        }
    }
}
