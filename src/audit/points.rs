//! The parameter points of the audit: seeded, reproducible, exact.
//!
//! Four points are drawn from a fixed-seed generator (SplitMix64) as small
//! rationals: unequal masses and radii, g ≠ 1, and one lower-cylinder bobbin
//! (k1 > 1) and one upper-cylinder bobbin (k2 > 1). Each also gets a general
//! start (θ0 > 0, θ̇0 > 0, ω0 ≠ 0). The special cases the paper names
//! (identical cylinders, footnotes 6, 8, 11, 12) are added as named points.

use crate::model::Params;
use rug::Rational;

/// The generator's seed (any change re-draws every random point).
pub const SEED: u64 = 0x00C7_1A0D_A0D1_7004;

/// SplitMix64 (Steele, Lea, Flood 2014): a tiny, portable, seeded generator.
struct SplitMix(u64);

impl SplitMix {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A rational n/den with n uniform in [lo·den, hi·den] (lo, hi as n/den pairs).
    fn draw(&mut self, lo: i64, hi: i64, den: i64) -> Rational {
        let span = (hi - lo + 1) as u64;
        let n = lo + (self.next() % span) as i64;
        Rational::from((n, den))
    }
}

/// One parameter point with its general start.
#[derive(Debug, Clone)]
pub struct Point {
    /// Short name used in the report ("P1", "I(1/2)", …).
    pub name: String,
    /// Physical parameters.
    pub params: Params,
    /// General start: θ0 > 0.
    pub theta0: Rational,
    /// General start: θ̇0 > 0.
    pub thetadot0: Rational,
    /// General start: ω0 ≠ 0.
    pub omega0: Rational,
    /// Drawn by the generator (the points every general check runs on).
    pub random: bool,
}

fn q(n: i64, d: i64) -> Rational {
    Rational::from((n, d))
}

/// The random points P1–P4 and the named special points, in a fixed order.
pub fn all() -> Vec<Point> {
    let mut rng = SplitMix(SEED);
    let mut out = Vec::new();
    for i in 0..4 {
        let (mut m1, mut m2, mut r1, mut r2);
        loop {
            m1 = rng.draw(4, 32, 8); // 1/2 … 4
            m2 = rng.draw(4, 32, 8);
            r1 = rng.draw(2, 16, 8); // 1/4 … 2
            r2 = rng.draw(2, 16, 8);
            if m1 != m2 && r1 != r2 {
                break;
            }
        }
        let k1 = if i == 3 {
            rng.draw(22, 50, 20) // a lower bobbin, 1.1 … 2.5
        } else {
            rng.draw(1, 20, 20)
        };
        let k2 = if i == 1 {
            rng.draw(22, 60, 20) // an upper bobbin, 1.1 … 3
        } else {
            rng.draw(2, 19, 20)
        };
        let g = rng.draw(4, 40, 4); // 1 … 10
        let theta0 = rng.draw(1, 8, 20); // 0.05 … 0.4
        let thetadot0 = rng.draw(1, 5, 20); // 0.05 … 0.25
        let mut omega0 = rng.draw(-10, 10, 10);
        if omega0 == 0 {
            omega0 = q(7, 10);
        }
        out.push(Point {
            name: format!("P{}", i + 1),
            params: Params {
                m1,
                m2,
                r1,
                r2,
                k1,
                k2,
                g,
            },
            theta0,
            thetadot0,
            omega0,
            random: true,
        });
    }
    out.push(Point {
        name: "S".into(),
        params: Params::identical_solid(),
        theta0: q(1, 10),
        thetadot0: q(1, 10),
        omega0: q(1, 2),
        random: false,
    });
    for (num, den) in [(1, 2), (3, 10), (3, 2)] {
        let k = q(num, den);
        out.push(Point {
            name: format!("I({num}/{den})"),
            params: Params {
                m1: q(3, 2),
                m2: q(3, 2),
                r1: q(2, 3),
                r2: q(2, 3),
                k1: k.clone(),
                k2: k,
                g: q(49, 5),
            },
            theta0: q(1, 10),
            thetadot0: q(1, 10),
            omega0: q(1, 2),
            random: false,
        });
    }
    out
}

/// A copy of `p` with k1 and k2 replaced and a new name.
pub fn with_k(p: &Point, k1: &Rational, k2: &Rational, name: &str) -> Point {
    let mut o = p.clone();
    o.params.k1 = k1.clone();
    o.params.k2 = k2.clone();
    o.name = name.to_string();
    o.random = false;
    o
}
