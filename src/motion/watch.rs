//! The events watched during a mode: the functions whose zeros end it.

use super::ctx::{friction_row, normal_row, row, tangent, Ctx};
use super::mode::{Mode, State};
use crate::integrate::solve::{Event, Watch};
use crate::mechanics::system::{self as sy, System};
use crate::model::Which;
use rug::Float;

/// What a watched zero means.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum What {
    /// N12 = 0: the cylinders part.
    Separation,
    /// N1 = 0: cylinder 1 leaves the floor.
    LiftOff,
    /// Cylinder 2 reaches the floor while still on cylinder 1.
    FloorImpact,
    /// A sticking contact's force reaches its cone.
    Cone(Which),
    /// A sliding contact's slip speed reaches 0.
    SlipZero(Which),
    /// The free relative normal acceleration of the cylinders changes sign:
    /// parting becomes lawful (or stops being so) while the contact holds.
    FreeNormal,
    /// θ reaches a requested angle (the end of `time --to`, `forces`).
    Target,
    /// θ is a little past the requested angle (where events near it are
    /// no longer looked for).
    Beyond,
    /// θ reaches the angle at which the cylinders are asked to part.
    PartAt,
}

/// The watched functions of a mode, each with its meaning.
pub struct Watches {
    /// The events handed to the integrators.
    pub events: Vec<Event>,
    /// What each event means.
    pub what: Vec<What>,
}

impl Watches {
    fn push(&mut self, what: What, name: &str, watch: Watch) {
        self.events.push(Event {
            name: name.into(),
            watch,
            terminal: true,
        });
        self.what.push(what);
    }
}

/// The free relative normal acceleration of the cylinders as a watch:
/// r θ̇² − g cos θ − ẍ1_free sin θ (ẍ1_free: cylinder 1's acceleration on its
/// floor alone, fixed by the mode).
pub fn free_normal(ctx: &Ctx, sys: &System, mode: Mode) -> Watch {
    let p = sys.prec;
    Watch::FreeNormal {
        th: sy::th(0),
        r: Float::with_val(p, &sys.rho[0] + &sys.rho[1]),
        g: Float::with_val(p, &sys.g),
        a: ctx.floor_accel_of(mode),
    }
}

/// The events watched in a mode: N12 = 0 (separation), N1 = 0 (lift-off,
/// unless cylinder 1 is held), cylinder 2 reaching the floor, the cone
/// μs N ∓ F = 0 of each sticking Coulomb contact, the slip speed of each
/// sliding Coulomb contact, and (`branch`) the free relative normal
/// acceleration, whose rise through 0 is a branch point.
pub fn of_mode(ctx: &Ctx, sys: &System, mode: Mode, branch: bool) -> Watches {
    let p = sys.prec;
    let mut w = Watches {
        events: Vec::new(),
        what: Vec::new(),
    };
    if let Some(i) = row(sys, sy::Row::Normal(0)) {
        w.push(What::Separation, "separation", Watch::Multiplier(i));
    }
    if !ctx.held {
        if let Some(i) = row(sys, sy::Row::FloorNormal) {
            w.push(What::LiftOff, "lift_off", Watch::Multiplier(i));
        }
    }
    // cylinder 2 reaching the floor while still on cylinder 1: y2 − r2 =
    // r1 + r cos θ − r2 = 0
    w.push(
        What::FloorImpact,
        "floor_impact",
        Watch::Height {
            th: sy::th(0),
            r: Float::with_val(p, &sys.rho[0] + &sys.rho[1]),
            offset: Float::with_val(p, &sys.rho[0] - &sys.rho[1]),
        },
    );
    for which in [Which::Floor, Which::Contact] {
        if !ctx.law(which).is_coulomb() {
            continue;
        }
        match mode.of(which) {
            State::Stick => {
                let (Some(n), Some(f), Some(mu)) = (
                    row(sys, normal_row(which)),
                    row(sys, friction_row(which)),
                    ctx.mu_s[which as usize].clone(),
                ) else {
                    continue;
                };
                for sign in [1i32, -1] {
                    w.push(
                        What::Cone(which),
                        &format!("cone:{}", which.name()),
                        Watch::Lin(vec![
                            (Watch::Multiplier(n), mu.clone()),
                            (Watch::Multiplier(f), Float::with_val(p, -sign)),
                        ]),
                    );
                }
            }
            State::Slip(sg) if sg != 0 => {
                let mut q = vec![Float::new(p); sys.nq()];
                q[sy::rr(0)] = Float::with_val(p, &sys.rho[0] + &sys.rho[1]);
                let terms = sys
                    .tangent_coeffs(tangent(which), &q)
                    .into_iter()
                    .map(|(i, c)| (Watch::Rate(i), c))
                    .collect();
                w.push(
                    What::SlipZero(which),
                    &format!("slip:{}", which.name()),
                    Watch::Lin(terms),
                );
            }
            _ => {}
        }
    }
    if branch {
        w.push(What::FreeNormal, "free_normal", free_normal(ctx, sys, mode));
    }
    w
}
