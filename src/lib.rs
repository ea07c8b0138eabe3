//! # cylroll — a reference oracle for a cylinder rolling on a rolling cylinder
//!
//! Computes, to a requested number of verified significant digits, the motion
//! of the system in *Cylinder Rolling on Another Rolling Cylinder* (cylinder 2
//! on top of cylinder 1, which stands on a horizontal floor), for every
//! contact law: rolling (μ = ∞), frictionless (μ = 0), Coulomb friction, and
//! a lower cylinder held by the floor — one motion for every law, with its
//! events, the free flight after separation and the first impact.
//!
//! Layers, each using only those below it: [`model`] (exact inputs, the law
//! of each contact) → [`mechanics`] (first-principles reduction of a
//! conservative phase to one degree of freedom, exact rational coefficients;
//! the constrained system of every mode) → [`numeric`] (quadrature, roots,
//! Chebyshev, intervals, the precision ladder) → [`integrate`] (the energy
//! route of a conservative phase, the spectral route in θ, GBS,
//! collocation) → [`motion`] (the hybrid motion: modes, events, branch
//! points, flight, impact) → [`oracle`] (the questions users ask → one typed
//! [`oracle::Answer`], verified) → [`golden`], [`check`], [`crosscheck`],
//! [`stack`], [`paper`], [`audit`], [`report`].
//!
//! Precision is always an explicit argument; no global state. Every number the
//! oracle returns has been computed at two working precisions and carries an
//! error bound combining their difference and the method's own estimate; only
//! digits that every number within the bound shares are printed. That accuracy
//! is *estimated*; [`oracle::rigorous`] proves digits by interval arithmetic
//! for the ideal models (see README, "Guarantees").
//!
//! ```
//! use cylroll::{exact::Exact, model::Model, oracle};
//! let model = Model::paper_default(Exact::zero());
//! let sep = oracle::separation(&model, &oracle::Options::digits(30)).unwrap();
//! // identical solid cylinders from rest at the top separate at θs = π/3
//! assert_eq!(sep.value("theta_s").unwrap().text, "1.04719755119659774615421446109");
//!
//! // from θ0 = 1/10 the cylinders may also part earlier: a branch point
//! let m = Model::paper_default(Exact::parse("theta0", "1/10", false).unwrap());
//! let sep = oracle::separation(&m, &oracle::Options::digits(12)).unwrap();
//! assert_eq!(sep.value("theta_indeterminate").unwrap().text, "0.965713174981");
//! ```

pub mod allocator;
pub mod audit;
pub mod cancel;
pub mod check;
pub mod crosscheck;
pub mod error;
pub mod exact;
pub mod golden;
pub mod integrate;
pub mod knobs;
pub mod mechanics;
pub mod model;
pub mod motion;
pub mod numeric;
pub mod oracle;
pub mod paper;
pub mod report;
pub mod stack;

pub use error::{Error, Result};
