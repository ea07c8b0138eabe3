//! # cylroll — a reference oracle for a cylinder rolling on a rolling cylinder
//!
//! Computes, to a requested number of verified significant digits, the motion
//! of the system in *Cylinder Rolling on Another Rolling Cylinder* (cylinder 2
//! on top of cylinder 1, which stands on a horizontal floor), for every
//! contact model: floor `roll` / `slip` / `fixed`, contact `roll` / `slip`.
//!
//! Data flow: [`model`] (exact inputs) → [`mechanics`] (first-principles
//! reduction to one degree of freedom, exact rational coefficients; a
//! Lagrange-multiplier route for the forces) → [`numeric`] (tanh-sinh,
//! bracketed roots, precision ladder) → [`oracle`] (the questions users ask,
//! answered as [`numeric::verify::Verified`] numbers).
//!
//! Precision is always an explicit argument; no global state. Every number the
//! oracle returns has been computed at two working precisions and carries an
//! error bound combining their difference and the method's own estimate; only
//! digits that every number within the bound shares are printed. That accuracy
//! is *estimated*; [`oracle::rigorous`] proves digits by interval arithmetic
//! for the ideal models (see README, "Guarantees").
//!
//! ```
//! use cylroll::{exact::Exact, model::Model, oracle::Oracle};
//! let model = Model::paper_default(Exact::zero());
//! let mut oracle = Oracle::new(&model, 30).unwrap();
//! let sep = oracle.separation().unwrap();
//! // identical solid cylinders from rest at the top separate at θs = π/3
//! assert_eq!(sep.theta_s.text, "1.04719755119659774615421446109");
//! ```

pub mod audit;
pub mod cancel;
pub mod check;
pub mod crosscheck;
pub mod error;
pub mod exact;
pub mod golden;
pub mod integrate;
pub mod mechanics;
pub mod model;
pub mod motion;
pub mod numeric;
pub mod oracle;
pub mod paper;
pub mod report;
pub mod stack;

pub use error::{Error, Result};
