//! Modes, phases and events: the vocabulary of the hybrid motion, as types.

use crate::model::Which;
use std::fmt;

/// The state of one contact during a mode.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum State {
    /// No relative tangential motion (rolling, or Coulomb sticking); the
    /// tangential force is a constraint force.
    Stick,
    /// Sliding; the sign is that of the slip speed (0 for a frictionless
    /// contact, where the direction does not matter).
    Slip(i8),
    /// Cylinder 1 held by the floor (a floor state only).
    Held,
}

impl State {
    /// `stick`, `slip+`, `slip-`, `slip` (frictionless), `held`.
    pub fn name(self) -> &'static str {
        match self {
            State::Stick => "stick",
            State::Slip(1) => "slip+",
            State::Slip(-1) => "slip-",
            State::Slip(_) => "slip",
            State::Held => "held",
        }
    }

    /// The state a contact ends up in whatever happens to the other one
    /// and to the motion: a contact that never changes state (rolling,
    /// frictionless, held) is *conservative*: no work is dissipated there.
    pub fn is_conservative(self) -> bool {
        matches!(self, State::Stick | State::Slip(0) | State::Held)
    }

    /// Parses [`State::name`].
    pub fn parse(s: &str) -> Option<State> {
        Some(match s {
            "stick" => State::Stick,
            "slip+" => State::Slip(1),
            "slip-" => State::Slip(-1),
            "slip" => State::Slip(0),
            "held" => State::Held,
            _ => return None,
        })
    }
}

impl fmt::Display for State {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The state of both contacts: a mode of the motion while the cylinders
/// touch.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Mode {
    /// The floor under cylinder 1.
    pub floor: State,
    /// The contact between the cylinders.
    pub contact: State,
}

impl fmt::Display for Mode {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "floor {}, contact {}", self.floor, self.contact)
    }
}

impl Mode {
    /// A short tag for tables: `stick/slip+` (floor/contact).
    pub fn tag(&self) -> String {
        format!("{}/{}", self.floor, self.contact)
    }

    /// The state of one contact.
    pub fn of(&self, w: Which) -> State {
        match w {
            Which::Floor => self.floor,
            Which::Contact => self.contact,
        }
    }

    /// Every contact rolling, sticking, frictionless or held: the energy
    /// integral holds while the motion stays in this mode.
    pub fn is_conservative(&self) -> bool {
        self.floor.is_conservative() && self.contact.is_conservative()
    }

    /// Parses [`Mode::tag`].
    pub fn parse(tag: &str) -> Option<Mode> {
        let (f, c) = tag.split_once('/')?;
        Some(Mode {
            floor: State::parse(f)?,
            contact: State::parse(c)?,
        })
    }
}

/// What the bodies are doing over a stretch of time: touching in a mode,
/// or flying apart after separation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Phase {
    /// The cylinders touch; each contact in its state.
    Contact(Mode),
    /// Cylinder 2 flies freely; cylinder 1 moves under its floor law alone
    /// (`floor` its state: sliding until a `stick` event in flight).
    Flight {
        /// The floor under cylinder 1.
        floor: State,
    },
}

impl Phase {
    /// The tag of a table's `mode` column: `stick/slip+`, or `flight`.
    pub fn tag(&self) -> String {
        match self {
            Phase::Contact(m) => m.tag(),
            Phase::Flight { .. } => "flight".into(),
        }
    }

    /// The mode while the cylinders touch.
    pub fn mode(&self) -> Option<Mode> {
        match self {
            Phase::Contact(m) => Some(*m),
            Phase::Flight { .. } => None,
        }
    }

    /// Whether the cylinders fly apart.
    pub fn is_flight(&self) -> bool {
        matches!(self, Phase::Flight { .. })
    }

    /// Parses [`Phase::tag`] (a flight's floor state is not in the tag:
    /// it is read as `stick`).
    pub fn parse(tag: &str) -> Option<Phase> {
        if tag == "flight" {
            return Some(Phase::Flight {
                floor: State::Stick,
            });
        }
        Mode::parse(tag).map(Phase::Contact)
    }

    /// Same phase as far as a table's `mode` column can tell.
    pub fn same_tag(&self, other: &Phase) -> bool {
        match (self, other) {
            (Phase::Flight { .. }, Phase::Flight { .. }) => true,
            (a, b) => a == b,
        }
    }
}

impl fmt::Display for Phase {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Phase::Contact(m) => m.fmt(f),
            Phase::Flight { .. } => f.write_str("flight"),
        }
    }
}

/// What happened at an event.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Kind {
    /// A sticking contact's needed |F|/N reached μs; it slips from here.
    SlipOnset,
    /// A slipping contact's slip speed returned to 0 and it sticks.
    Stick,
    /// A slipping contact's slip speed returned to 0 and it slips the other way.
    SlipReversal,
    /// The cylinders part (N12 = 0, or no closed mode is consistent and the
    /// free motion separates, or on the `part` branch where parting became
    /// lawful).
    Separation,
    /// N1 = 0: cylinder 1 leaves the floor; the motion after it is outside
    /// the model, which ends there.
    LiftOff,
    /// The first impact: cylinder 2 reaching the floor or cylinder 1 again
    /// after separation, or reaching the floor while still on cylinder 1.
    /// Impact laws are outside the model, which ends there.
    Impact,
    /// A branch point: from here on the rigid-body model has more than one
    /// consistent continuation (the cylinders may stay together or part).
    Indeterminate,
}

impl Kind {
    /// The JSON name.
    pub fn name(self) -> &'static str {
        match self {
            Kind::SlipOnset => "slip_onset",
            Kind::Stick => "stick",
            Kind::SlipReversal => "slip_reversal",
            Kind::Separation => "separation",
            Kind::LiftOff => "lift_off",
            Kind::Impact => "impact",
            Kind::Indeterminate => "indeterminate",
        }
    }

    /// Parses [`Kind::name`].
    pub fn parse(s: &str) -> Option<Kind> {
        [
            Kind::SlipOnset,
            Kind::Stick,
            Kind::SlipReversal,
            Kind::Separation,
            Kind::LiftOff,
            Kind::Impact,
            Kind::Indeterminate,
        ]
        .into_iter()
        .find(|k| k.name() == s)
    }

    /// Whether the model ends at this event.
    pub fn ends(self) -> bool {
        matches!(self, Kind::LiftOff | Kind::Impact)
    }
}

impl fmt::Display for Kind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// What cylinder 2 hits at the first impact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Surface {
    /// Cylinder 2 lands on the floor after separation.
    Floor,
    /// Cylinder 2 touches cylinder 1 again.
    Cylinder,
    /// Cylinder 2 reaches the floor while still on cylinder 1 (before any
    /// separation).
    FloorInContact,
}

impl Surface {
    /// `floor`, `cylinder`, `floor_in_contact`.
    pub fn name(self) -> &'static str {
        match self {
            Surface::Floor => "floor",
            Surface::Cylinder => "cylinder",
            Surface::FloorInContact => "floor_in_contact",
        }
    }
}

/// How the motion ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum End {
    /// At the first impact (impact laws are outside the model).
    Impact(Surface),
    /// At the lift-off of cylinder 1 (outside the model).
    LiftOff,
}

impl End {
    /// `impact` (with its surface) or `lift_off`.
    pub fn name(self) -> String {
        match self {
            End::Impact(s) => format!("impact on the {}", s.name().replace('_', " ")),
            End::LiftOff => "lift-off of cylinder 1".into(),
        }
    }
}

/// Which continuation to follow where the rigid-body motion is not unique
/// (from a branch point the cylinders may stay together or part).
#[derive(Debug, Clone, PartialEq, Default)]
pub enum Branch {
    /// The contact persists while it can (the limit of stiff compliant
    /// contact; the default).
    #[default]
    Stay,
    /// The cylinders part at the first instant they may (what
    /// velocity-level complementarity engines do).
    Part,
    /// The cylinders part where θ reaches the given angle, which must lie in
    /// the window where parting is lawful.
    PartAt(crate::exact::Exact),
}

impl Branch {
    /// `stay`, `part`, `part-at θ`.
    pub fn name(&self) -> String {
        match self {
            Branch::Stay => "stay".into(),
            Branch::Part => "part".into(),
            Branch::PartAt(t) => format!("part-at {t}"),
        }
    }
}
