//! The one typed answer of every question, for every contact law.

use super::ideal::rigorous::Proved;
use crate::model::{Model, Which};
use crate::motion::{Branch, End, Kind, Mode, Phase, Route};
use crate::numeric::verify::Verified;

/// The questions users ask.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Question {
    /// The motion to its end: its events, separation, the first impact.
    Separation,
    /// The time at which θ first reaches an angle.
    Time,
    /// The forces, rates and slip speeds where θ first reaches an angle.
    Forces,
    /// Every column at given times.
    Trajectory,
}

impl Question {
    /// The subcommand's name.
    pub fn name(self) -> &'static str {
        match self {
            Question::Separation => "separation",
            Question::Time => "time",
            Question::Forces => "forces",
            Question::Trajectory => "trajectory",
        }
    }
}

/// One event with verified time and angle.
#[derive(Debug, Clone)]
pub struct EventAnswer {
    /// What happened.
    pub kind: Kind,
    /// The contact concerned (None for an impact).
    pub which: Option<Which>,
    /// The phase entered (None: the end of the model).
    pub phase: Option<Phase>,
    /// Time.
    pub t: Verified,
    /// θ there.
    pub theta: Verified,
    /// At a branch point, every other continuation consistent there (`part`,
    /// and any other closed mode, e.g. `stick/slip+`); empty otherwise.
    pub also: Vec<String>,
}

/// One row of a trajectory.
#[derive(Debug, Clone)]
pub struct Row {
    /// The values, in [`crate::motion::COLUMNS`] order.
    pub values: Vec<Verified>,
    /// The phase the row belongs to.
    pub phase: Phase,
    /// The row's time could not be told apart from this event's at the
    /// precision reachable: the row is the state at the event (the columns
    /// continuous there; the forces and accelerations of the phase before).
    pub at_event: Option<usize>,
}

/// The answer to a question about a model.
#[derive(Debug, Clone)]
pub struct Answer {
    /// The question.
    pub question: Question,
    /// The model, as given.
    pub model: Model,
    /// Significant digits requested.
    pub digits: u32,
    /// The branch followed where the motion is not unique.
    pub branch: Branch,
    /// The contacts' states at t = 0 (None for a start at rest exactly at
    /// the top, which never moves).
    pub start_mode: Option<Mode>,
    /// The events from the start, in time order (for `time`, `forces`,
    /// `trajectory`: those up to the angle or the last time).
    pub events: Vec<EventAnswer>,
    /// How the motion ended, when the answer follows it to its end.
    pub end: Option<End>,
    /// The named values, in order (`theta_s`, `t_s`, …; `t`; `F1`, …).
    pub values: Vec<Verified>,
    /// Proved enclosures of values (`--rigorous`), parallel to `values`.
    pub proved: Vec<Option<Proved>>,
    /// The columns of the rows, in order (`trajectory`): names of
    /// [`crate::motion::COLUMNS`] and `mode` (the phase of the row); each
    /// row's `values` are the numeric ones, in this order.
    pub columns: Vec<String>,
    /// The rows (`trajectory`).
    pub rows: Vec<Row>,
    /// Proved enclosures of rows (`--rigorous`, ideal models).
    pub proved_rows: Vec<Vec<Proved>>,
    /// The phase at the angle (`time`, `forces`).
    pub phase: Option<Phase>,
    /// The routes that computed the phases, in order.
    pub routes: Vec<Route>,
    /// Findings in words.
    pub notes: Vec<String>,
}

impl Answer {
    /// The value named `name`.
    pub fn value(&self, name: &str) -> Option<&Verified> {
        self.values.iter().find(|v| v.name == name)
    }

    /// The first event of a kind.
    pub fn event(&self, kind: Kind) -> Option<&EventAnswer> {
        self.events.iter().find(|e| e.kind == kind)
    }
}
