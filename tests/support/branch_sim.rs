//! Two planar simulations of the two cylinders for `tests/branch_physics.rs`, in `f64`,
//! sharing nothing with the cylroll library: each body is a free rigid disc in the plane
//! (x, y, counter-clockwise angle a), and only the contact models couple them.
//!
//! * [`run_compliant`]: penalty contacts. Normal force `max(0, k δ + c δ̇)` at the floor and
//!   between the cylinders (δ the overlap), tangential spring-slider `-k_t ξ - c_t u`
//!   (ξ the integrated slip `u` of the contact points) limited to `μ N`, integrated by the
//!   classical fourth-order Runge–Kutta method with a fixed step.
//! * [`run_stepper`]: a velocity-level complementarity time-stepper (Stewart–Trinkle /
//!   Anitescu–Potra; Bullet and Pymunk solve such steps by sequential impulses): per step the
//!   contact impulses `P` satisfy `0 ≤ P_n ⊥ φ/h + J_n v⁺ ≥ 0` and Coulomb's law
//!   `|P_t| ≤ μ P_n` with `J_t v⁺ = 0` inside the cone, solved by projected Gauss–Seidel;
//!   then `q⁺ = q + h v⁺`.
//!
//! Conventions as in the README: θ is the line of centres clockwise from the vertical,
//! φ1 clockwise (a1 = -φ1), ψ2 counter-clockwise (a2 = ψ2); F21 is the tangential force of
//! cylinder 1 on cylinder 2 along t = (cos θ, -sin θ), F1 the floor's on cylinder 1 along +x.

/// Masses, radii, inertia factors (I = k m r²) and gravity.
#[derive(Clone, Copy, Debug)]
pub struct Params {
    pub m1: f64,
    pub m2: f64,
    pub r1: f64,
    pub r2: f64,
    pub k1: f64,
    pub k2: f64,
    pub g: f64,
}

impl Params {
    fn r(&self) -> f64 {
        self.r1 + self.r2
    }

    /// Inverse of the diagonal mass matrix of q = (x1, y1, a1, x2, y2, a2).
    fn inv_mass(&self) -> [f64; 6] {
        [
            1.0 / self.m1,
            1.0 / self.m1,
            1.0 / (self.k1 * self.m1 * self.r1 * self.r1),
            1.0 / self.m2,
            1.0 / self.m2,
            1.0 / (self.k2 * self.m2 * self.r2 * self.r2),
        ]
    }
}

/// A state of the closed rigid motion and its contact forces (the fixture's `pre_*` keys).
#[derive(Clone, Copy, Debug)]
pub struct RigidState {
    pub theta: f64,
    pub theta_dot: f64,
    pub x1: f64,
    pub x1_dot: f64,
    pub phi1: f64,
    pub phi1_dot: f64,
    pub psi2: f64,
    pub psi2_dot: f64,
    pub n12: f64,
    pub f21: f64,
    pub n1: f64,
    pub f1: f64,
}

/// Coordinates or velocities of both bodies: (x1, y1, a1, x2, y2, a2).
pub type Q = [f64; 6];

impl RigidState {
    /// Positions and velocities of both bodies, the centres `overlap_floor` below the floor's
    /// surface and `overlap_contact` closer than r1 + r2 (the compliant model's static
    /// deflections); both 0 for the rigid stepper.
    fn bodies(&self, p: &Params, overlap_floor: f64, overlap_contact: f64) -> (Q, Q) {
        let (s, c) = self.theta.sin_cos();
        let y1 = p.r1 - overlap_floor;
        let d = p.r() - overlap_contact;
        let q = [
            self.x1,
            y1,
            -self.phi1,
            self.x1 + d * s,
            y1 + d * c,
            self.psi2,
        ];
        let r = p.r();
        let v = [
            self.x1_dot,
            0.0,
            -self.phi1_dot,
            self.x1_dot + r * c * self.theta_dot,
            -r * s * self.theta_dot,
            self.psi2_dot,
        ];
        (q, v)
    }
}

/// θ: the direction of the line of centres, clockwise from the vertical.
pub fn line_of_centres(q: &Q) -> f64 {
    (q[3] - q[0]).atan2(q[4] - q[1])
}

fn gap(p: &Params, q: &Q) -> f64 {
    (q[3] - q[0]).hypot(q[4] - q[1]) - p.r()
}

fn dot(a: &Q, b: &Q) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// Normal and tangential Jacobian rows of the floor contact and of the contact between the
/// cylinders, and their gaps: rows (n_floor, t_floor, n_12, t_12), gaps (floor, 12).
/// t_12 = (cos θ, -sin θ): its row gives s12 = r θ̇ + r2 ψ̇2 - r1 φ̇1 (README), the floor's
/// tangential row s1 = ẋ1 - r1 φ̇1.
fn jacobian(p: &Params, q: &Q) -> ([Q; 4], [f64; 2]) {
    let (dx, dy) = (q[3] - q[0], q[4] - q[1]);
    let len = dx.hypot(dy);
    let (nx, ny) = (dx / len, dy / len);
    let (tx, ty) = (ny, -nx);
    let rows = [
        [0.0, 1.0, 0.0, 0.0, 0.0, 0.0],
        [1.0, 0.0, p.r1, 0.0, 0.0, 0.0],
        [-nx, -ny, 0.0, nx, ny, 0.0],
        [-tx, -ty, p.r1, tx, ty, p.r2],
    ];
    (rows, [q[1] - p.r1, len - p.r()])
}

// ------------------------------------------------------------------ compliant contacts

/// Penalty contact: normal stiffness `k` and damping `c`, tangential stiffness `kt` and
/// damping `ct`, Coulomb limit `mu`.
#[derive(Clone, Copy, Debug)]
pub struct Compliant {
    pub k: f64,
    pub c: f64,
    pub kt: f64,
    pub ct: f64,
    pub mu: f64,
}

impl Compliant {
    /// Stiffness `k` at both contacts, damping critical for the mass `m_eff`, the same
    /// tangential stiffness and damping.
    pub fn new(k: f64, mu: f64, m_eff: f64) -> Self {
        let c = 2.0 * (k * m_eff).sqrt();
        Self {
            k,
            c,
            kt: k,
            ct: c,
            mu,
        }
    }
}

/// Flat state: q (6), v (6), tangential spring elongations (floor, contact).
type Y = [f64; 14];

/// Contact forces of a compliant state: (N1, F1, N12, F21) (on cylinder 1 from the floor, on
/// cylinder 2 from cylinder 1).
/// Also the tangential slip speeds (floor, contact) that drive the spring elongations.
fn compliant_forces(p: &Params, m: &Compliant, y: &Y) -> ([f64; 4], [f64; 2]) {
    let q: Q = y[0..6].try_into().unwrap();
    let v: Q = y[6..12].try_into().unwrap();
    let (rows, gaps) = jacobian(p, &q);
    let mut out = [0.0; 4];
    let mut slip = [0.0; 2];
    for (i, xi) in [y[12], y[13]].into_iter().enumerate() {
        let overlap = -gaps[i];
        let un = dot(&rows[2 * i], &v);
        let ut = dot(&rows[2 * i + 1], &v);
        slip[i] = ut;
        if overlap > 0.0 {
            let n = (m.k * overlap - m.c * un).max(0.0);
            let f = if n > 0.0 {
                let lim = m.mu * n;
                (-m.kt * xi - m.ct * ut).clamp(-lim, lim)
            } else {
                0.0
            };
            out[2 * i] = n;
            out[2 * i + 1] = f;
        }
    }
    (out, slip)
}

fn compliant_rhs(p: &Params, m: &Compliant, y: &Y) -> Y {
    let q: Q = y[0..6].try_into().unwrap();
    let (rows, _) = jacobian(p, &q);
    let (f, slip) = compliant_forces(p, m, y);
    // generalised force: gravity plus J^T (N, F) of each contact (on body 2 along +n, +t)
    let mut gen = [0.0, -p.m1 * p.g, 0.0, 0.0, -p.m2 * p.g, 0.0];
    for (row, force) in rows.iter().zip(f) {
        for (gk, rk) in gen.iter_mut().zip(row) {
            *gk += rk * force;
        }
    }
    let minv = p.inv_mass();
    let mut d = [0.0; 14];
    d[..6].copy_from_slice(&y[6..12]);
    for k in 0..6 {
        d[6 + k] = gen[k] * minv[k];
    }
    d[12] = slip[0];
    d[13] = slip[1];
    d
}

fn rk4(p: &Params, m: &Compliant, y: &Y, h: f64) -> Y {
    let add = |a: &Y, b: &Y, s: f64| -> Y {
        let mut o = *a;
        for (ok, bk) in o.iter_mut().zip(b) {
            *ok += s * bk;
        }
        o
    };
    let k1 = compliant_rhs(p, m, y);
    let k2 = compliant_rhs(p, m, &add(y, &k1, h / 2.0));
    let k3 = compliant_rhs(p, m, &add(y, &k2, h / 2.0));
    let k4 = compliant_rhs(p, m, &add(y, &k3, h));
    let mut o = *y;
    for i in 0..14 {
        o[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    }
    o
}

/// What a compliant run saw.
#[derive(Clone, Copy, Debug)]
pub struct CompliantRun {
    /// θ at the first step where the force between the cylinders is 0 (None: never).
    pub first_open_theta: Option<f64>,
    /// θ and t of the last step with a force between the cylinders (it is 0 ever after,
    /// until the gap exceeds 1e-2 r).
    pub part_theta: f64,
    pub part_t: f64,
    /// The least N12 while θ ≤ θ_watch (to show the contact is loaded through θ*).
    pub min_n12_to_watch: f64,
}

/// Compliant run from the rigid state `start` at time `t0` (the springs preloaded with the
/// rigid forces: overlaps N/k, spring elongations -F/k_t), with step `dt`, until the
/// cylinders are 1e-2 r apart or `t_max`.
pub fn run_compliant(
    p: &Params,
    m: &Compliant,
    start: &RigidState,
    t0: f64,
    dt: f64,
    t_max: f64,
    theta_watch: f64,
) -> CompliantRun {
    let (q, v) = start.bodies(p, start.n1 / m.k, start.n12 / m.k);
    let mut y = [0.0; 14];
    y[..6].copy_from_slice(&q);
    y[6..12].copy_from_slice(&v);
    y[12] = -start.f1 / m.kt;
    y[13] = -start.f21 / m.kt;
    let mut t = t0;
    let mut run = CompliantRun {
        first_open_theta: None,
        part_theta: f64::NAN,
        part_t: f64::NAN,
        min_n12_to_watch: f64::INFINITY,
    };
    while t < t_max {
        y = rk4(p, m, &y, dt);
        t += dt;
        let (f, _) = compliant_forces(p, m, &y);
        // spring-slider: an open contact forgets its elongation, a sliding one stays on the
        // cone
        for i in 0..2 {
            let lim = m.mu * f[2 * i] / m.kt;
            y[12 + i] = if f[2 * i] > 0.0 {
                y[12 + i].clamp(-lim, lim)
            } else {
                0.0
            };
        }
        let q: Q = y[0..6].try_into().unwrap();
        let theta = line_of_centres(&q);
        if theta <= theta_watch {
            run.min_n12_to_watch = run.min_n12_to_watch.min(f[2]);
        }
        if f[2] > 0.0 {
            run.part_theta = theta;
            run.part_t = t;
        } else if run.first_open_theta.is_none() {
            run.first_open_theta = Some(theta);
        }
        if gap(p, &q) > 1e-2 * p.r() {
            break;
        }
    }
    run
}

// ------------------------------------------------------------------ velocity-level LCP

/// What a time-stepper run saw.
#[derive(Clone, Copy, Debug)]
pub struct StepperRun {
    /// θ and t of the last step whose impulse between the cylinders is positive (0 ever
    /// after, until they are 1e-2 r apart).
    pub part_theta: f64,
    pub part_t: f64,
    /// θ at the first step with no impulse between the cylinders.
    pub first_open_theta: Option<f64>,
    /// Where the parting solution first becomes admissible: the first step whose margin
    /// w = φ/h + J_n v (cylinder contact, with the floor's impulses alone) is ≥ 0, and θ
    /// interpolated linearly in w between that step and the one before.
    pub admissible_step_theta: Option<f64>,
    pub admissible_theta: Option<f64>,
    /// Most projected Gauss–Seidel sweeps any step needed.
    pub max_sweeps: usize,
}

/// How the stepper's projected Gauss–Seidel starts and stops.
#[derive(Clone, Copy, Debug)]
pub struct Solver {
    /// Coulomb coefficients of the floor and of the contact between the cylinders
    /// (`f64::INFINITY`: rolling, 0: frictionless).
    pub mu_floor: f64,
    pub mu_contact: f64,
    /// Each step starts from `warm` times the previous step's impulses (0: from zero).
    pub warm: f64,
    /// At most this many sweeps per step (else until no impulse changes by 1e-13 m g h).
    pub max_sweeps: usize,
}

/// Projected Gauss–Seidel on the contacts `cnts` (0: floor, 1: between the cylinders; per
/// contact its normal row, then its tangential row clamped to the cone). Returns the sweeps.
fn pgs(
    a: &[[f64; 4]; 4],
    b: &[f64; 4],
    imp: &mut [f64; 4],
    cnts: &[usize],
    s: &Solver,
    tol: f64,
) -> usize {
    let res =
        |imp: &[f64; 4], k: usize| -> f64 { b[k] + (0..4).map(|l| a[k][l] * imp[l]).sum::<f64>() };
    let mut sweeps = 0;
    loop {
        sweeps += 1;
        let mut change: f64 = 0.0;
        for &cnt in cnts {
            let (i, j) = (2 * cnt, 2 * cnt + 1);
            let pn = (imp[i] - res(imp, i) / a[i][i]).max(0.0);
            change = change.max((pn - imp[i]).abs());
            imp[i] = pn;
            let mu = if cnt == 0 { s.mu_floor } else { s.mu_contact };
            let pt = if imp[i] > 0.0 && mu > 0.0 {
                let lim = mu * imp[i];
                (imp[j] - res(imp, j) / a[j][j]).clamp(-lim, lim)
            } else {
                0.0
            };
            change = change.max((pt - imp[j]).abs());
            imp[j] = pt;
        }
        if change <= tol || sweeps >= s.max_sweeps {
            return sweeps;
        }
    }
}

/// Velocity-level complementarity stepper from the rigid state `start` at `t0`, step `h`,
/// until the cylinders are 1e-2 r apart or `t_max`.
pub fn run_stepper(
    p: &Params,
    start: &RigidState,
    t0: f64,
    h: f64,
    t_max: f64,
    s: &Solver,
) -> StepperRun {
    let (mut q, mut v) = start.bodies(p, 0.0, 0.0);
    let minv = p.inv_mass();
    let mut imp = [0.0; 4];
    let tol = 1e-13 * p.m2 * p.g * h;
    let mut t = t0;
    let mut run = StepperRun {
        part_theta: f64::NAN,
        part_t: f64::NAN,
        first_open_theta: None,
        admissible_step_theta: None,
        admissible_theta: None,
        max_sweeps: 0,
    };
    let mut prev: Option<(f64, f64)> = None;
    while t < t_max {
        let theta_before = line_of_centres(&q);
        let (rows, gaps) = jacobian(p, &q);
        let mut vfree = v;
        vfree[1] -= h * p.g;
        vfree[4] -= h * p.g;
        // Delassus matrix A = J M^-1 J^T and the free (biased) constraint velocities b
        let mut a = [[0.0; 4]; 4];
        for (ai, ri) in a.iter_mut().zip(&rows) {
            for (aij, rj) in ai.iter_mut().zip(&rows) {
                *aij = (0..6).map(|k| ri[k] * minv[k] * rj[k]).sum();
            }
        }
        let mut b = [0.0; 4];
        for (i, bi) in b.iter_mut().enumerate() {
            *bi = dot(&rows[i], &vfree) + if i % 2 == 0 { gaps[i / 2] / h } else { 0.0 };
        }
        // margin of the parting solution: the floor's impulses alone
        if run.admissible_theta.is_none() {
            let mut alone = [0.0; 4];
            let exact = Solver {
                max_sweeps: 100_000,
                ..*s
            };
            pgs(&a, &b, &mut alone, &[0], &exact, tol);
            let w = b[2] + a[2][0] * alone[0] + a[2][1] * alone[1];
            if w >= 0.0 {
                run.admissible_step_theta = Some(theta_before);
                run.admissible_theta = Some(match prev {
                    Some((th0, w0)) => th0 + (theta_before - th0) * (-w0) / (w - w0),
                    None => theta_before,
                });
            }
            prev = Some((theta_before, w));
        }
        for x in imp.iter_mut() {
            *x *= s.warm;
        }
        let sweeps = pgs(&a, &b, &mut imp, &[0, 1], s, tol);
        run.max_sweeps = run.max_sweeps.max(sweeps);
        for (k, vk) in v.iter_mut().enumerate() {
            *vk = vfree[k] + minv[k] * (0..4).map(|i| rows[i][k] * imp[i]).sum::<f64>();
        }
        for (qk, vk) in q.iter_mut().zip(&v) {
            *qk += h * vk;
        }
        t += h;
        if imp[2] > 0.0 {
            run.part_theta = theta_before;
            run.part_t = t - h;
        } else if run.first_open_theta.is_none() {
            run.first_open_theta = Some(theta_before);
        }
        if gap(p, &q) > 1e-2 * p.r() {
            break;
        }
    }
    run
}
