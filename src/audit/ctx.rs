//! The audit's shared state: the parameter points, the cases built from them
//! (cached), and the oracle's separation angles (cached).

use super::points::{self, Point};
use super::truth::{model_of, Case, StartKind, ORACLE_DIGITS, PREC};
use crate::error::{Error, Result};
use crate::model::{Contact, Floor};
use crate::oracle::Oracle;
use crate::paper::{Sym, X};
use rug::Float;
use std::collections::HashMap;
use std::rc::Rc;

type Key = (String, u8, u8, StartKind, bool);

fn code(floor: Floor, contact: Contact) -> (u8, u8) {
    (
        match floor {
            Floor::Roll => 0,
            Floor::Slip => 1,
            Floor::Fixed => 2,
        },
        match contact {
            Contact::Roll => 0,
            Contact::Slip => 1,
        },
    )
}

/// Points, cached cases and cached separation angles.
pub struct Ctx {
    /// Every point, random first.
    pub points: Vec<Point>,
    cases: HashMap<Key, Rc<Case>>,
    thetas: HashMap<(String, u8, u8), X>,
    seps: HashMap<(String, u8, u8), Rc<crate::oracle::Separation>>,
}

impl Default for Ctx {
    fn default() -> Self {
        Self::new()
    }
}

impl Ctx {
    /// The points of [`points::all`], nothing computed yet.
    pub fn new() -> Self {
        Ctx {
            points: points::all(),
            cases: HashMap::new(),
            thetas: HashMap::new(),
            seps: HashMap::new(),
        }
    }

    /// The random points P1–P4.
    pub fn random(&self) -> Vec<Point> {
        self.points.iter().filter(|p| p.random).cloned().collect()
    }

    /// The random points and the paper's identical solid cylinders.
    pub fn general(&self) -> Vec<Point> {
        self.points
            .iter()
            .filter(|p| p.random || p.name == "S")
            .cloned()
            .collect()
    }

    /// The named point.
    pub fn point(&self, name: &str) -> Result<Point> {
        self.points
            .iter()
            .find(|p| p.name == name)
            .cloned()
            .ok_or_else(|| Error::invalid("point", name, "no such audit point"))
    }

    /// The case of `point` (cached). `timed`: positions at the oracle's times.
    pub fn case(
        &mut self,
        point: &Point,
        floor: Floor,
        contact: Contact,
        start: StartKind,
        timed: bool,
    ) -> Result<Rc<Case>> {
        let (f, c) = code(floor, contact);
        let key = (point.name.clone(), f, c, start, timed);
        if let Some(k) = self.cases.get(&key) {
            return Ok(k.clone());
        }
        let case = Rc::new(Case::new(point, floor, contact, start, timed)?);
        self.cases.insert(key, case.clone());
        Ok(case)
    }

    /// The oracle's separation for a start from rest at the top (cached).
    pub fn separation(
        &mut self,
        point: &Point,
        floor: Floor,
        contact: Contact,
    ) -> Result<Rc<crate::oracle::Separation>> {
        let (f, c) = code(floor, contact);
        let key = (point.name.clone(), f, c);
        if let Some(s) = self.seps.get(&key) {
            return Ok(s.clone());
        }
        let model = model_of(point, floor, contact, StartKind::Rest)?;
        let mut o = Oracle::new(&model, ORACLE_DIGITS)?;
        let s = Rc::new(o.separation()?);
        self.thetas
            .insert(key.clone(), X(Float::with_val(PREC, &s.theta_s.value)));
        self.seps.insert(key, s.clone());
        Ok(s)
    }

    /// θs (N12 = 0) from the oracle at 60 digits, start from rest at the top.
    pub fn theta_s(&mut self, point: &Point, floor: Floor, contact: Contact) -> Result<X> {
        let (f, c) = code(floor, contact);
        let key = (point.name.clone(), f, c);
        if !self.thetas.contains_key(&key) {
            self.separation(point, floor, contact)?;
        }
        self.thetas
            .get(&key)
            .cloned()
            .ok_or_else(|| Error::not_physical("separation angle missing"))
    }

    /// The symbols of the rest case of `point` at θ (from rest at the top, δ = θ).
    pub fn sym_at(
        &mut self,
        point: &Point,
        floor: Floor,
        contact: Contact,
        theta: &X,
    ) -> Result<Sym> {
        let case = self.case(point, floor, contact, StartKind::Rest, false)?;
        let st = case.dynm.state(&theta.0);
        case.sym(&st, &Float::new(PREC))
    }
}
