//! Command-line interface: parse, call the library, print. No physics here.

mod prove;
mod render;
mod stream;

use clap::{Args, Parser, Subcommand, ValueEnum};
use cylroll::error::{Error, Result};
use cylroll::exact::Exact;
use cylroll::model::input::{self, FRICTION_KEYS, MODEL_KEYS};
use cylroll::model::Model;
use cylroll::motion::Branch;
use cylroll::oracle::{self, Options};
use rug::Rational;
use std::io::Write;
use stream::Output;

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
    /// The motion to its end: events, separation (theta_s, t_s), the branch point, the first impact
    Separation {
        #[command(flatten)]
        common: Common,
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
    /// Rows t, theta, theta_dot, theta_ddot, phi1, phi2, x1, x2, y2, x1_dot, phi1_dot, x2_dot, y2_dot, phi2_dot, F1, N1, F21, N12, s1, s12, work, mode at given times
    Trajectory {
        #[command(flatten)]
        common: Common,
        /// Comma-separated times
        #[arg(long, allow_hyphen_values = true, conflicts_with_all = ["t_end", "steps", "times_file"])]
        times: Option<String>,
        /// A file of times (separated by commas, spaces or line ends)
        #[arg(long, conflicts_with_all = ["t_end", "steps"])]
        times_file: Option<std::path::PathBuf>,
        /// Last time of an equally spaced grid (with --steps)
        #[arg(long, allow_hyphen_values = true, requires = "steps")]
        t_end: Option<String>,
        /// Number of intervals of the grid 0, t_end/N, ..., t_end (1 to 100000)
        #[arg(long, requires = "t_end", allow_hyphen_values = true, value_parser = steps_arg)]
        steps: Option<u32>,
        /// The columns to print, in this order (comma-separated; default all):
        /// t, theta, theta_dot, ..., work, mode. `t,theta` computes theta alone
        #[arg(long)]
        columns: Option<String>,
    },
    /// Render every golden case (golden/cases/*.toml) into golden/data/<case>.json and .csv
    Golden {
        /// The golden directory
        #[arg(long, default_value = "golden")]
        dir: std::path::PathBuf,
    },
    /// Judge another program's CSV against the oracle (exit 1 if a tolerance is exceeded)
    #[command(group(clap::ArgGroup::new("reference").required(true).args(["case", "params"])))]
    Check {
        /// The candidate CSV (header row with golden column names; t required)
        candidate: std::path::PathBuf,
        /// The golden case it simulates (one of the built-in cases: the file stems of golden/cases)
        #[arg(long)]
        case: Option<String>,
        /// Or the model it simulates, as a parameter file (the keys of --params; a golden case
        /// file is one)
        #[arg(long)]
        params: Option<std::path::PathBuf>,
        /// Relative tolerance of every column (>= 0)
        #[arg(long, default_value_t = 1e-8, allow_hyphen_values = true, value_parser = tol_arg)]
        rtol: f64,
        /// Absolute tolerance of every column (>= 0), in units of the column's natural scale
        /// (time sqrt(r/g), lengths r, velocities sqrt(g r), forces (m1+m2) g, work m2 g r)
        #[arg(long, default_value_t = 1e-10, allow_hyphen_values = true, value_parser = tol_arg)]
        atol: f64,
        /// One column's tolerance, COLUMN=RTOL[,ATOL] (ATOL in the column's own units); repeatable
        #[arg(long = "tol", value_name = "COLUMN=RTOL[,ATOL]", allow_hyphen_values = true, value_parser = tol_override_arg)]
        tols: Vec<cylroll::check::Override>,
        /// The branch to judge against where the motion is not unique: auto (the one the
        /// candidate took: it parted at theta* -> part, at the closed branch's end -> stay,
        /// inside the window -> part there; before theta* fails), stay or part
        #[arg(long, value_enum, default_value_t = CheckBranchArg::Auto, conflicts_with = "part_at")]
        branch: CheckBranchArg,
        /// Judge against the reference that parts where theta reaches this angle (inside the window)
        #[arg(long, allow_hyphen_values = true)]
        part_at: Option<String>,
        /// Tolerance of an event (slip onset, parting, ...), in radians of theta [default: 1e-3]
        #[arg(long, allow_hyphen_values = true, value_parser = tol_arg)]
        event_tol: Option<f64>,
        /// Rows after the end of the model (the first impact): report (left out, counted, the
        /// first named) or refuse (exit 2)
        #[arg(long, value_enum, default_value_t = PastEndArg::Report)]
        past_end: PastEndArg,
        /// Significant digits of the oracle values compared against, 1 to 2000
        #[arg(long, default_value_t = 20, allow_hyphen_values = true, value_parser = digits_arg)]
        digits: u32,
        /// Largest number of data rows accepted (the candidate is read in chunks, in bounded memory)
        #[arg(long, default_value_t = 1_000_000, allow_hyphen_values = true, value_parser = rows_arg)]
        max_rows: usize,
        /// Read --case NAME from DIR/cases/NAME.toml instead of the built-in cases
        #[arg(long, value_name = "DIR", requires = "case")]
        golden: Option<std::path::PathBuf>,
        /// The candidate's schema: 1 (phi2 in the paper's gauge, the first golden schema) or 2;
        /// by default 2 (a header that is a full schema-1 column list gets a note where phi2 fails)
        #[arg(long, value_parser = schema_arg)]
        schema: Option<u32>,
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
pub enum BranchArg {
    Stay,
    Part,
}

/// `check --past-end`.
#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
pub enum PastEndArg {
    Report,
    Refuse,
}

/// `check --branch`.
#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
pub enum CheckBranchArg {
    Auto,
    Stay,
    Part,
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
    /// Floor under cylinder 1: roll (mu = inf) | slip (frictionless, mu = 0) | fixed (held)
    #[arg(long)]
    floor: Option<String>,
    /// Contact between the cylinders: roll (mu = inf) | slip (frictionless, mu = 0)
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
    /// Coulomb friction at both contacts (the floor's unless it is fixed): inf, a number >= 0, or S,K
    #[arg(long, allow_hyphen_values = true, conflicts_with_all = ["mu_floor", "mu_contact"])]
    mu: Option<String>,
    /// Where the rigid-body motion is not unique: stay (the contact persists while it can; the
    /// limit of stiff compliant contact) or part (the cylinders part at the first instant they
    /// may, as velocity-level complementarity engines do)
    #[arg(long, value_enum, default_value_t = BranchArg::Stay, conflicts_with = "part_at")]
    branch: BranchArg,
    /// Part where theta reaches this angle (inside the window where parting is lawful)
    #[arg(long, allow_hyphen_values = true)]
    part_at: Option<String>,
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
    int_arg(s, 1, cylroll::check::MAX_ROWS_LIMIT as u64).map(|v| v as usize)
}

/// `--schema`: 1 or 2.
fn schema_arg(s: &str) -> std::result::Result<u32, String> {
    int_arg(s, 1, 2).map(|v| v as u32)
}

/// `--tol COLUMN=RTOL[,ATOL]`.
fn tol_override_arg(s: &str) -> std::result::Result<cylroll::check::Override, String> {
    cylroll::check::parse_override(s).map_err(|e| match e {
        Error::InvalidParameter { allowed, .. } => allowed,
        other => other.to_string(),
    })
}

/// A tolerance: 0, or a finite number from 1e-300 on
/// ([`cylroll::check::tolerance_of`]).
fn tol_arg(s: &str) -> std::result::Result<f64, String> {
    cylroll::check::tolerance_of(s).ok_or_else(|| cylroll::check::TOLERANCE_ALLOWED.into())
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

    /// The key/value pairs from the defaults, then `--params`, then the
    /// flags; and the keys whose value is the file's.
    fn pairs(&self) -> Result<(input::Pairs, Vec<String>)> {
        let mut vals = input::Pairs::new();
        if let Some(path) = &self.params {
            vals = input::read_params(path)?;
        }
        let mut from_file: Vec<String> = vals.keys().cloned().collect();
        for k in MODEL_KEYS.iter().chain(FRICTION_KEYS.iter()) {
            if let Some(v) = self.flag(k) {
                vals.insert(k.to_string(), v);
                from_file.retain(|f| f != k);
            }
        }
        if let Some(mu) = &self.mu {
            // Coulomb friction at both contacts (a held cylinder keeps its floor)
            let held = vals
                .get("floor")
                .is_some_and(|f| f.trim().eq_ignore_ascii_case("fixed"));
            if !held {
                vals.insert("mu_floor".into(), mu.clone());
            }
            vals.insert("mu_contact".into(), mu.clone());
            from_file.retain(|f| f != "mu_contact" && (held || f != "mu_floor"));
        }
        Ok((vals, from_file))
    }

    /// The model: every contact's law from `--floor`, `--contact`,
    /// `--mu-floor`, `--mu-contact`, `--mu` (and `--params`).
    pub fn model(&self) -> Result<Model> {
        // a start at the top is the ideal models' limit θ0 → 0+ and is
        // judged by the command that runs
        let (pairs, from_file) = self.pairs()?;
        input::model_from_pairs(&pairs).map_err(|mut e| {
            // a coefficient --mu gave is named as the user wrote it
            if let (Some(mu), Error::InvalidParameter { name, value, .. }) = (&self.mu, &mut e) {
                if (name == "mu_floor" || name == "mu_contact") && value == mu {
                    *name = "mu".into();
                }
            }
            // the file is named when the value at fault is its own
            let file_key = matches!(&e, Error::InvalidParameter { name, .. }
                if from_file.contains(name));
            match &self.params {
                Some(path) if file_key || !self.flags_given() => in_file(e, path),
                _ => e,
            }
        })
    }

    fn flags_given(&self) -> bool {
        MODEL_KEYS
            .iter()
            .chain(FRICTION_KEYS.iter())
            .any(|k| self.flag(k).is_some())
            || self.mu.is_some()
    }

    /// How to answer: the digits and the branch.
    pub fn options(&self) -> Result<Options> {
        let branch = match (&self.part_at, self.branch) {
            (Some(a), _) => Branch::PartAt(Exact::parse("part-at", a, true)?),
            (None, BranchArg::Part) => Branch::Part,
            (None, BranchArg::Stay) => Branch::Stay,
        };
        Ok(Options {
            digits: self.digits,
            branch,
            method: cylroll::motion::Method::Auto,
        })
    }
}

use input::in_file;

/// Where each requested time was given, for messages: the parameter
/// (`times`, `times-file PATH`) and each entry's place in it.
struct Origins {
    param: String,
    /// The line of each entry of a file (empty for a list: entry i alone).
    lines: Vec<usize>,
}

impl Origins {
    /// The name of entry `i` (from 0) in a message: `times: entry 3`,
    /// `times-file t.txt: entry 3 (line 2)`; made only for a message.
    fn name(&self, i: usize) -> String {
        match self.lines.get(i) {
            Some(line) => format!("{}: entry {} (line {line})", self.param, i + 1),
            None => format!("{}: entry {}", self.param, i + 1),
        }
    }

    /// Entry `i` parsed, a refusal naming it.
    fn parse(&self, i: usize, text: &str) -> Result<Exact> {
        Exact::parse(&self.param, text, false)
            .map_err(|e| e.map_invalid(|_, value| (self.name(i), value)))
    }

    /// The times in order and not negative, each refusal naming its entry.
    fn check(&self, times: &[Exact]) -> Result<()> {
        for (i, t) in times.iter().enumerate() {
            if t.signum() < 0 {
                return Err(Error::invalid(
                    &self.name(i),
                    t,
                    "must be >= 0 (the start is at t = 0)",
                ));
            }
            if i > 0 && t.coef < times[i - 1].coef {
                return Err(Error::invalid(
                    &self.name(i),
                    t,
                    format!(
                        "must be ascending: it is before the entry before it, {}",
                        times[i - 1]
                    ),
                ));
            }
        }
        Ok(())
    }

    /// An error of the oracle about a time, naming the entry it quotes (the
    /// first with that text: the times are ascending, so the first at fault).
    fn locate(&self, e: Error, times: &[Exact]) -> Error {
        e.map_invalid(|name, value| {
            if name != "times" {
                return (name, value);
            }
            let name = match times.iter().position(|t| t.to_string() == value) {
                Some(i) => self.name(i),
                None => self.param.clone(),
            };
            (name, value)
        })
    }
}

/// The times of `--times t1,t2,...`, each entry named by its place.
fn parse_list(s: &str) -> Result<(Vec<Exact>, Origins)> {
    let origins = Origins {
        param: "times".into(),
        lines: Vec::new(),
    };
    let times = s
        .split(',')
        .enumerate()
        .map(|(i, t)| origins.parse(i, t))
        .collect::<Result<Vec<_>>>()?;
    Ok((times, origins))
}

/// Largest times file read, in bytes.
const MAX_TIMES_FILE: u64 = 64 << 20;

/// The times of a `--times-file`: separated by commas, spaces or line ends;
/// a refusal of an entry names the file, the entry's number and its line.
fn times_file(path: &std::path::Path) -> Result<(Vec<Exact>, Origins)> {
    let text = input::read_input(path, "times-file", MAX_TIMES_FILE)?;
    let mut origins = Origins {
        param: format!("times-file {}", path.display()),
        lines: Vec::new(),
    };
    let mut times = Vec::new();
    for (line, content) in text.split('\n').enumerate() {
        for t in content
            .split(|c: char| c == ',' || c.is_whitespace())
            .filter(|s| !s.is_empty())
        {
            origins.lines.push(line + 1);
            times.push(origins.parse(times.len(), t)?);
        }
    }
    if times.is_empty() {
        return Err(Error::invalid(
            "times-file",
            path.display(),
            "holds no times",
        ));
    }
    Ok((times, origins))
}

/// The times of `trajectory`, and where each was given (none for a grid).
fn trajectory_times(
    times: Option<String>,
    file: Option<std::path::PathBuf>,
    t_end: Option<String>,
    steps: Option<u32>,
) -> Result<(Vec<Exact>, Option<Origins>)> {
    let (times, origins) = match (times, file, t_end, steps) {
        (Some(list), _, _, _) => parse_list(&list)?,
        (None, Some(path), _, _) => times_file(&path)?,
        (None, None, Some(te), Some(n)) => {
            if n == 0 || n > 100_000 {
                return Err(Error::invalid("steps", n, "must be between 1 and 100000"));
            }
            let te = Exact::parse("t-end", &te, false)?;
            if te.signum() <= 0 {
                return Err(Error::invalid("t-end", &te, "must be > 0"));
            }
            let grid = (0..=n)
                .map(|i| Exact::rational(&te.coef * Rational::from((i, n))))
                .collect();
            return Ok((grid, None));
        }
        _ => {
            return Err(Error::invalid(
                "times",
                "",
                "give --times t1,t2,..., --times-file FILE or --t-end T --steps N",
            ))
        }
    };
    origins.check(&times)?;
    Ok((times, Some(origins)))
}

/// A refusal of a time of the grid `--t-end T --steps N` names `t-end`
/// (the time refused is the grid's, not one the user gave): "invalid t-end
/// = "7": the grid's time 6 (step 6 of 7) must not be after …".
fn on_grid(e: Error, t_end: &str, steps: u32) -> Error {
    match e {
        Error::InvalidParameter {
            name,
            value,
            allowed,
        } if name == "times" => {
            // which step of the grid: t·N/T
            let step = Exact::parse("times", &value, false)
                .ok()
                .zip(Exact::parse("t-end", t_end, false).ok())
                .map(|(t, te)| (&t.coef * Rational::from(steps)) / &te.coef)
                .filter(|k| *k.denom() == 1);
            let at = match step {
                Some(k) => format!("the grid's time {value} (step {k} of {steps})"),
                None => format!("the grid's time {value}"),
            };
            Error::invalid("t-end", t_end, format!("{at} {allowed}"))
        }
        other => other,
    }
}

/// Runs the command and returns the text to print on standard output.
pub fn run(cli: Cli) -> Result<(Output, i32)> {
    let (common, answer) = match cli.command {
        Command::Golden { dir } => {
            return cylroll::golden::write_all(&dir).map(|s| (Output::Text(s), 0))
        }
        Command::Check {
            candidate,
            case,
            params,
            rtol,
            atol,
            tols,
            branch,
            part_at,
            event_tol,
            past_end,
            digits,
            max_rows,
            golden,
            schema,
            format,
        } => {
            use cylroll::check::BranchRequest;
            let case = match (case, params) {
                (Some(name), _) => match &golden {
                    Some(dir) => cylroll::golden::find_case(dir, &name)?,
                    None => cylroll::golden::builtin_case(&name)?,
                },
                (None, Some(path)) => {
                    cylroll::golden::read_case(&path, "params", path.display().to_string())?
                }
                (None, None) => unreachable!("clap requires --case or --params"),
            };
            let branch = match (part_at, branch) {
                (Some(a), _) => BranchRequest::PartAt(Exact::parse("part-at", &a, true)?),
                (None, CheckBranchArg::Auto) => BranchRequest::Auto,
                (None, CheckBranchArg::Stay) => BranchRequest::Stay,
                (None, CheckBranchArg::Part) => BranchRequest::Part,
            };
            let mut lim = cylroll::check::Limits::new(rtol, atol, digits);
            lim.tols = tols;
            lim.max_rows = max_rows;
            lim.schema = schema;
            lim.branch = branch;
            if let Some(e) = event_tol {
                lim.event_tol = e;
            }
            lim.past_end = match past_end {
                PastEndArg::Report => cylroll::check::PastEnd::Report,
                PastEndArg::Refuse => cylroll::check::PastEnd::Refuse,
            };
            let src = cylroll::check::File::new(&candidate);
            let rep = cylroll::check::check_source(&src, &case, &lim)?;
            let out = match format {
                Format::Json => rep.json(),
                Format::Csv => rep.csv(),
                Format::Text => rep.text(),
            };
            return Ok((Output::Text(out), rep.exit_code()));
        }
        Command::Audit { equation, out } => {
            return cylroll::audit::run(equation.as_deref(), &out).map(|s| (Output::Text(s), 0))
        }
        Command::Report { out, quiet } => {
            return cylroll::report::run(&out, !quiet).map(|s| (Output::Text(s), 0))
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
                    .map(|s| (Output::Text(s), 0));
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
            return Ok((Output::Text(out), 0));
        }
        Command::Separation { common } => {
            let model = common.model()?;
            let opts = common.options()?;
            let mut ans = oracle::separation(&model, &opts)?;
            if common.rigorous {
                prove::separation(&model, &mut ans);
            }
            (common, ans)
        }
        Command::Time { common, to } => {
            let model = common.model()?;
            let opts = common.options()?;
            let theta = Exact::parse("to", &to, true)?;
            prove::supported(&common, &model)?;
            let mut ans = oracle::time(&model, &theta, &opts)?;
            if common.rigorous {
                prove::time(&model, &theta, &mut ans);
            }
            (common, ans)
        }
        Command::Forces { common, theta } => {
            let model = common.model()?;
            let opts = common.options()?;
            let th = Exact::parse("theta", &theta, true)?;
            prove::supported(&common, &model)?;
            let mut ans = oracle::forces(&model, &th, &opts)?;
            if common.rigorous {
                prove::forces(&model, &th, &mut ans);
            }
            (common, ans)
        }
        Command::Trajectory {
            common,
            times,
            times_file,
            t_end,
            steps,
            columns,
        } => {
            let columns = match columns {
                Some(c) => oracle::parse_columns(&c)?,
                None => oracle::all_columns(),
            };
            let grid = t_end.clone().zip(steps);
            let (times, origins) = trajectory_times(times, times_file, t_end, steps)?;
            let model = common.model()?;
            let opts = common.options()?;
            prove::supported(&common, &model)?;
            let out = stream::trajectory(
                &model,
                &times,
                &opts,
                &columns,
                common.rigorous,
                common.format,
            )
            .map_err(|e| match (&origins, &grid) {
                (Some(o), _) => o.locate(e, &times),
                (None, Some((te, n))) => on_grid(e, te, *n),
                (None, None) => e,
            })?;
            return Ok((out, 0));
        }
    };
    Ok((Output::Text(render::render(answer, common.format)), 0))
}

/// Entry point used by `main`: prints or reports the error, returns the exit code.
pub fn main_with(args: Vec<String>) -> i32 {
    // a closed standard output (`>&-`): Rust's runtime reopens a closed
    // descriptor 1 on /dev/null before main, so the answer would vanish
    // with exit 0; the probe saw it closed before that
    if stdout_was_closed() {
        eprintln!("error: cannot write standard output: it is closed (nothing was computed)");
        return 4;
    }
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
            if let Err(e) = out.write_to(&mut so).and_then(|_| so.flush()) {
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

/// Descriptor 1 was closed when the process started (`>&-`), as the probe
/// [`probe_stdout`] found it before Rust's runtime replaced it.
static STDOUT_CLOSED_AT_START: std::sync::atomic::AtomicBool =
    std::sync::atomic::AtomicBool::new(false);

/// The probe, run by the C runtime among the program's initialisers (the
/// `.init_array` section), before Rust's runtime: that reopens a closed
/// descriptor 0–2 on /dev/null, after which a closed standard output can no
/// longer be told from `/dev/null` opened read-write, as Python's
/// `subprocess.DEVNULL` opens it (an ordinary place to discard output).
#[cfg(target_os = "linux")]
#[used]
#[link_section = ".init_array"]
static PROBE_STDOUT: extern "C" fn() = probe_stdout;

#[cfg(target_os = "linux")]
extern "C" fn probe_stdout() {
    // SAFETY: fcntl(F_GETFD) on a descriptor number reads its flags and
    // touches no memory of ours
    if unsafe { libc::fcntl(1, libc::F_GETFD) } == -1 {
        STDOUT_CLOSED_AT_START.store(true, std::sync::atomic::Ordering::Relaxed);
    }
}

/// Whether standard output was closed when the process started.
fn stdout_was_closed() -> bool {
    STDOUT_CLOSED_AT_START.load(std::sync::atomic::Ordering::Relaxed)
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
