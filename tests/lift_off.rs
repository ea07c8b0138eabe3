//! Lift-off of cylinder 1 from the floor while N1 > 0 is never a consistent
//! continuation, for any contact law, masses, radii, inertias and state.
//!
//! The claim (README, "Where the motion is not unique"): with the floor
//! contact open, the two cylinders feel only gravity and their mutual
//! contact force. Gravity accelerates both alike, and a tangential contact
//! force moves the centres perpendicular to the line of centres, so the
//! centre distance obeys ρ̈ = r θ̇² + N12 (1/m1 + 1/m2) whatever the
//! tangential law: the contact stays closed (ρ̈ = 0) only with
//! N12 = −r θ̇² m1 m2/(m1 + m2) ≤ 0. A closed contact is then inadmissible
//! (θ̇ ≠ 0) or carries no force (θ̇ = 0, when the rolling constraint's force
//! vanishes too); an open one carries none. Either way ÿ1 = −g < 0: the
//! floor cannot open.
//!
//! The test does not use that formula: it assembles Newton–Euler for two
//! free discs in the plane from their definitions (contact points, the
//! exact time derivatives of the gap and of the slip velocity), solves the
//! constrained system for the accelerations and contact forces in `f64`
//! with nalgebra, for a rolling contact and for a sliding one, over random
//! parameters and states, and checks that N12 never comes out positive
//! (and equals the value above), and that at θ̇ = 0 the closed contact
//! carries no force and cylinder 1 falls freely.

use nalgebra::{DMatrix, DVector};
use proptest::prelude::*;

/// ẑ × d
fn perp(d: [f64; 2]) -> [f64; 2] {
    [-d[1], d[0]]
}
fn dot(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}
/// (d × f)·ẑ
fn cross(d: [f64; 2], f: [f64; 2]) -> f64 {
    d[0] * f[1] - d[1] * f[0]
}
fn add(a: [f64; 2], b: [f64; 2]) -> [f64; 2] {
    [a[0] + b[0], a[1] + b[1]]
}
fn scale(k: f64, a: [f64; 2]) -> [f64; 2] {
    [k * a[0], k * a[1]]
}

/// Two free discs touching, the line of centres at θ from the vertical.
struct Pair {
    m: [f64; 2],
    i: [f64; 2],
    r: [f64; 2],
    g: f64,
    theta: f64,
    /// Velocities: centre of 1, ω1, ω2 (the centre of 2 follows from θ̇).
    v1: [f64; 2],
    theta_dot: f64,
    w: [f64; 2],
}

/// The contact law kept while the contact is closed.
#[derive(Clone, Copy, Debug)]
enum Law {
    /// No slip: the slip velocity's derivative vanishes.
    Roll,
    /// Sliding with F21 = −μ N12 sgn(slip).
    Slide(f64),
}

impl Pair {
    fn n(&self) -> [f64; 2] {
        [self.theta.sin(), self.theta.cos()]
    }
    fn t(&self) -> [f64; 2] {
        [self.theta.cos(), -self.theta.sin()]
    }
    fn rsum(&self) -> f64 {
        self.r[0] + self.r[1]
    }
    /// Centre velocity of 2: d/dt of c1 + r n.
    fn v2(&self) -> [f64; 2] {
        add(self.v1, scale(self.rsum() * self.theta_dot, self.t()))
    }
    /// Arms from the centres to the contact point.
    fn arms(&self) -> [[f64; 2]; 2] {
        [scale(self.r[0], self.n()), scale(-self.r[1], self.n())]
    }
    /// Slip velocity t·(v_P2 − v_P1) of the material points at the contact.
    fn slip(&self) -> f64 {
        let [d1, d2] = self.arms();
        let vp1 = add(self.v1, scale(self.w[0], perp(d1)));
        let vp2 = add(self.v2(), scale(self.w[1], perp(d2)));
        dot(self.t(), add(vp2, scale(-1.0, vp1)))
    }

    /// Accelerations (a1x, a1y, α1, a2x, a2y, α2) and contact forces
    /// (N12, F21) with the floor open and the contact closed under `law`.
    fn closed(&self, law: Law) -> ([f64; 6], f64, f64) {
        let (n, t) = (self.n(), self.t());
        let [d1, d2] = self.arms();
        let td = self.theta_dot;
        // unknowns z = (a1x, a1y, α1, a2x, a2y, α2, N, F); force on 2 is N n + F t at P2
        let dim = 8;
        let mut a = DMatrix::<f64>::zeros(dim, dim);
        let mut b = DVector::<f64>::zeros(dim);
        // Newton–Euler: m a − (contact) = gravity
        for (row, (body, sign)) in [(0usize, -1.0), (1usize, 1.0)].iter().enumerate() {
            let base = 3 * row;
            let d = if *body == 0 { d1 } else { d2 };
            a[(base, base)] = self.m[*body];
            a[(base + 1, base + 1)] = self.m[*body];
            a[(base + 2, base + 2)] = self.i[*body];
            for (col, dir) in [(6usize, n), (7usize, t)] {
                let f = scale(*sign, dir);
                a[(base, col)] = -f[0];
                a[(base + 1, col)] = -f[1];
                a[(base + 2, col)] = -cross(d, f);
            }
            b[base + 1] = -self.m[*body] * self.g;
        }
        // the gap ρ = |c2 − c1|: ρ̈ = n·(a2 − a1) + |v2 − v1|²/ρ (v2 − v1 ⊥ n) = 0
        let vrel = add(self.v2(), scale(-1.0, self.v1));
        a[(6, 0)] = -n[0];
        a[(6, 1)] = -n[1];
        a[(6, 3)] = n[0];
        a[(6, 4)] = n[1];
        b[6] = -dot(vrel, vrel) / self.rsum();
        match law {
            Law::Roll => {
                // s = t·(v2 + ω2 ẑ×d2 − v1 − ω1 ẑ×d1); ṡ = ṫ·(…) + t·(a2 + α2 ẑ×d2 +
                // ω2 ẑ×ḋ2 − a1 − α1 ẑ×d1 − ω1 ẑ×ḋ1) = 0, ṫ = −θ̇ n, ḋ1 = r1 θ̇ t, ḋ2 = −r2 θ̇ t
                let vp1 = add(self.v1, scale(self.w[0], perp(d1)));
                let vp2 = add(self.v2(), scale(self.w[1], perp(d2)));
                let tdot = scale(-td, n);
                let dd1 = scale(self.r[0] * td, t);
                let dd2 = scale(-self.r[1] * td, t);
                a[(7, 0)] = -t[0];
                a[(7, 1)] = -t[1];
                a[(7, 2)] = -dot(t, perp(d1));
                a[(7, 3)] = t[0];
                a[(7, 4)] = t[1];
                a[(7, 5)] = dot(t, perp(d2));
                b[7] = -(dot(tdot, add(vp2, scale(-1.0, vp1)))
                    + dot(t, scale(self.w[1], perp(dd2)))
                    - dot(t, scale(self.w[0], perp(dd1))));
            }
            Law::Slide(mu) => {
                // F + μ sgn(s) N = 0
                a[(7, 7)] = 1.0;
                a[(7, 6)] = mu * self.slip().signum();
            }
        }
        let z = a.lu().solve(&b).expect("a nonsingular constrained system");
        let acc = [z[0], z[1], z[2], z[3], z[4], z[5]];
        (acc, z[6], z[7])
    }
}

#[allow(clippy::too_many_arguments)]
fn pair(
    m: [f64; 2],
    k: [f64; 2],
    r: [f64; 2],
    g: f64,
    theta: f64,
    v1: [f64; 2],
    theta_dot: f64,
    w1: f64,
    slip: f64,
) -> Pair {
    let mut p = Pair {
        m,
        i: [k[0] * m[0] * r[0] * r[0], k[1] * m[1] * r[1] * r[1]],
        r,
        g,
        theta,
        v1,
        theta_dot,
        w: [w1, 0.0],
    };
    // ω2 such that the slip velocity is `slip` (it is linear in ω2)
    let s0 = p.slip();
    p.w[1] = 1.0;
    let s1 = p.slip();
    p.w[1] = (slip - s0) / (s1 - s0);
    p
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn with_the_floor_open_a_closed_contact_needs_n12_of_minus_r_thetadot2_reduced_mass(
        m1 in 0.05f64..20.0, m2 in 0.05f64..20.0,
        k1 in 0.0f64..2.0, k2 in 0.0f64..2.0,
        r1 in 0.05f64..20.0, r2 in 0.05f64..20.0,
        g in 0.1f64..30.0,
        theta in 0.0f64..3.1,
        v1x in -5.0f64..5.0, v1y in -5.0f64..5.0,
        theta_dot in -5.0f64..5.0, w1 in -10.0f64..10.0,
        slip in prop_oneof![Just(0.0f64), -3.0f64..3.0],
        mu in 0.0f64..20.0,
    ) {
        let slide = slip != 0.0;
        // rolling needs inertia (k > 0) to have a nonsingular constrained system
        prop_assume!(slide || (k1 > 1e-3 && k2 > 1e-3));
        let p = pair([m1, m2], [k1, k2], [r1, r2], g, theta, [v1x, v1y], theta_dot, w1, slip);
        let law = if slide { Law::Slide(mu) } else { Law::Roll };
        let (acc, n12, _f21) = p.closed(law);
        let want = -(r1 + r2) * theta_dot * theta_dot * m1 * m2 / (m1 + m2);
        let scale = 1.0 + want.abs() + (m1 + m2) * g;
        prop_assert!((n12 - want).abs() <= 1e-9 * scale, "N12 = {n12}, want {want} ({law:?})");
        // never a compressive force: the closed contact is inadmissible (θ̇ ≠ 0) ...
        prop_assert!(n12 <= 1e-9 * scale);
        // ... and where it carries none, cylinder 1 falls freely: ÿ1 = −g < 0
        if theta_dot == 0.0 {
            prop_assert!((acc[1] + g).abs() <= 1e-9 * scale, "y1'' = {} with g = {g}", acc[1]);
        }
    }
}

#[test]
fn at_rest_the_closed_contact_carries_no_force_and_the_lower_cylinder_falls() {
    // θ̇ = 0 exactly (the start from rest): N12 = 0 and, rolling, F21 = 0 too
    for theta in [0.0, 0.1, 1.0, 1.5, 2.5] {
        let p = pair(
            [1.0, 3.0],
            [0.5, 1.0],
            [1.0, 0.4],
            9.81,
            theta,
            [0.0, 0.0],
            0.0,
            0.0,
            0.0,
        );
        let (acc, n12, f21) = p.closed(Law::Roll);
        assert!(
            n12.abs() < 1e-12 && f21.abs() < 1e-12,
            "N12 = {n12}, F21 = {f21}"
        );
        assert!((acc[1] + 9.81).abs() < 1e-12, "y1'' = {}", acc[1]);
    }
}
