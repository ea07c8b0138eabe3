//! The table of cos/sin(kπ/2N) every transform and point is built from
//! ([`Roots`]), and the complex FFT of mixed radix 2, 3, 5 on `rug::Float`
//! by recursive decimation in time with twiddles from that table, with the
//! transform of N real values by one complex FFT of length N/2: the fast
//! cosine transforms of [`super::ChebFit`] rest on them.

use rug::float::Constant;
use rug::ops::NegAssign;
use rug::{Assign, Float};

/// cos and sin of kπ/(2N) for k = 0..=N (the first quadrant of the 4N-th
/// roots of unity), at `prec` + 32 bits.
#[derive(Debug, Clone)]
pub struct Roots {
    pub(super) n: usize,
    cos: Vec<Float>,
    sin: Vec<Float>,
}

impl Roots {
    /// The table for N points at `prec` bits (plus guard bits).
    pub fn new(n: usize, prec: u32) -> Self {
        let p = prec + 32;
        let mut cos = vec![Float::new(p); n + 1];
        let mut sin = vec![Float::new(p); n + 1];
        let step = Float::with_val(p, Constant::Pi) / (2 * n) as u64;
        let (s1, c1) = Float::with_val(p, &step).sin_cos(Float::new(p));
        let half = n / 2;
        let mut t = Float::new(p);
        for k in 0..=half {
            if k % 32 == 0 {
                let a = Float::with_val(p, &step * k as u64);
                let (s, c) = a.sin_cos(Float::new(p));
                cos[k] = c;
                sin[k] = s;
            } else {
                // (c + is)(c1 + is1)
                let (head, tail) = cos.split_at_mut(k);
                let (sh, st) = sin.split_at_mut(k);
                let (c, s) = (&head[k - 1], &sh[k - 1]);
                tail[0].assign(c * &c1);
                t.assign(s * &s1);
                tail[0] -= &t;
                st[0].assign(s * &c1);
                t.assign(c * &s1);
                st[0] += &t;
            }
        }
        // cos(kπ/2N) = sin((N − k)π/2N)
        for k in half + 1..=n {
            cos[k] = sin[n - k].clone();
            sin[k] = cos[n - k].clone();
        }
        Roots { n, cos, sin }
    }

    /// Points N of the table.
    pub fn n(&self) -> usize {
        self.n
    }

    /// (cos a, sin a) for a = mπ/(2N), any m (the signs folded in by `neg`
    /// flags: the value is (±cos-entry, ±sin-entry)).
    pub(super) fn cis(&self, m: usize) -> (&Float, bool, &Float, bool) {
        let n = self.n;
        let m = m % (4 * n);
        if m <= n {
            (&self.cos[m], false, &self.sin[m], false)
        } else if m <= 2 * n {
            let j = 2 * n - m;
            (&self.cos[j], true, &self.sin[j], false)
        } else if m <= 3 * n {
            let j = m - 2 * n;
            (&self.cos[j], true, &self.sin[j], true)
        } else {
            let j = 4 * n - m;
            (&self.cos[j], false, &self.sin[j], true)
        }
    }

    /// (cos a, sin a) for a = mπ/(2N), signs applied, at the table's
    /// precision.
    pub(super) fn cos_sin(&self, m: usize) -> (Float, Float) {
        let (c, nc, s, ns) = self.cis(m);
        let c = if nc { -c.clone() } else { c.clone() };
        let s = if ns { -s.clone() } else { s.clone() };
        (c, s)
    }

    /// The k-th Chebyshev point of the first kind, cos((2k+1)π/2N), at `p` bits.
    pub fn point(&self, k: usize, p: u32) -> Float {
        let (c, neg, _, _) = self.cis(2 * k + 1);
        let x = Float::with_val(p, c);
        if neg {
            -x
        } else {
            x
        }
    }
}

/// z ← z·e^(−2πi m/N) (a twiddle of the length-N transform), with three
/// scratch Floats (no allocation).
fn rotate(re: &mut Float, im: &mut Float, roots: &Roots, m: usize, t: &mut [Float; 3]) {
    if m % roots.n == 0 {
        return;
    }
    // e^(−iφ), φ = 4m·π/(2N): (a + ib)(c' − i s') with c' = ±c, s' = ±s
    let (c, nc, s, ns) = roots.cis(4 * m);
    let [t0, t1, t2] = t;
    // real: a c' + b s'
    t0.assign(&*re * c);
    t1.assign(&*im * s);
    match (nc, ns) {
        (false, false) => t2.assign(&*t0 + &*t1),
        (false, true) => t2.assign(&*t0 - &*t1),
        (true, false) => t2.assign(&*t1 - &*t0),
        (true, true) => {
            t2.assign(&*t0 + &*t1);
            t2.neg_assign();
        }
    }
    // imag: b c' − a s'
    t0.assign(&*im * c);
    t1.assign(&*re * s);
    match (nc, ns) {
        (false, false) => im.assign(&*t0 - &*t1),
        (false, true) => im.assign(&*t0 + &*t1),
        (true, false) => {
            im.assign(&*t0 + &*t1);
            im.neg_assign();
        }
        (true, true) => im.assign(&*t1 - &*t0),
    }
    std::mem::swap(re, t2);
}

/// In place: X_k = Σ_j x_j e^(−2πi jk/n) for the n = len entries, where n
/// divides the table's N (its twiddles are table entries). Mixed radix
/// 2, 3, 5 by recursive decimation in time, out of place into scratch
/// buffers (no allocation below the top).
pub(super) fn fft(re: &mut [Float], im: &mut [Float], roots: &Roots, p: u32) {
    let n = re.len();
    if n <= 1 {
        return;
    }
    let mut ore = vec![Float::new(p); n];
    let mut oim = vec![Float::new(p); n];
    let mut w = Work {
        t: [Float::new(p), Float::new(p), Float::new(p)],
        zr: vec![Float::new(p); 5],
        zi: vec![Float::new(p); 5],
        a: Float::new(p),
        b: Float::new(p),
        acc_r: Float::new(p),
        acc_i: Float::new(p),
        v: vec![Float::new(p); 16],
    };
    let k = Consts {
        s3: (roots.n % 3 == 0).then(|| roots.cos_sin(4 * roots.n / 3).1),
        c5: (roots.n % 5 == 0).then(|| {
            let (c1, s1) = roots.cos_sin(4 * roots.n / 5);
            let (c2, s2) = roots.cos_sin(8 * roots.n / 5);
            [c1, c2, s1, s2]
        }),
    };
    fft_rec(re, im, 0, 1, n, &mut ore, &mut oim, roots, &mut w, &k);
    for (x, y) in re.iter_mut().zip(ore.iter_mut()) {
        std::mem::swap(x, y);
    }
    for (x, y) in im.iter_mut().zip(oim.iter_mut()) {
        std::mem::swap(x, y);
    }
}

/// Scratch of [`fft_rec`].
struct Work {
    t: [Float; 3],
    zr: Vec<Float>,
    zi: Vec<Float>,
    a: Float,
    b: Float,
    acc_r: Float,
    acc_i: Float,
    /// Scratch of the radix-3 and radix-5 butterflies.
    v: Vec<Float>,
}

/// The constants of the radix-3 and radix-5 butterflies.
struct Consts {
    /// sin(2π/3) (where N has the factor 3).
    s3: Option<Float>,
    /// cos(2π/5), cos(4π/5), sin(2π/5), sin(4π/5) (where N has the factor 5).
    c5: Option<[Float; 4]>,
}

/// The DFT of the n entries x[off + j·stride] into out[0..n].
#[allow(clippy::too_many_arguments)]
fn fft_rec(
    re: &[Float],
    im: &[Float],
    off: usize,
    stride: usize,
    n: usize,
    ore: &mut [Float],
    oim: &mut [Float],
    roots: &Roots,
    w: &mut Work,
    consts: &Consts,
) {
    if n == 1 {
        ore[0].assign(&re[off]);
        oim[0].assign(&im[off]);
        return;
    }
    let r = [2usize, 3, 5]
        .into_iter()
        .find(|r| n % r == 0)
        .expect("n has only the prime factors 2, 3, 5");
    let m = n / r;
    // the r subsequences x_{jr+q}, each transformed into out[q m .. (q+1) m]
    for q in 0..r {
        fft_rec(
            re,
            im,
            off + q * stride,
            stride * r,
            m,
            &mut ore[q * m..(q + 1) * m],
            &mut oim[q * m..(q + 1) * m],
            roots,
            w,
            consts,
        );
    }
    // the table's N is a multiple of n: e^(−2πi e/n) = e^(−2πi (e N/n)/N)
    let scale = roots.n / n;
    for k in 0..m {
        for q in 0..r {
            w.zr[q].assign(&ore[q * m + k]);
            w.zi[q].assign(&oim[q * m + k]);
            if q > 0 {
                let (zr, zi) = (&mut w.zr[q], &mut w.zi[q]);
                rotate(zr, zi, roots, q * k * scale, &mut w.t);
            }
        }
        if r == 2 {
            ore[k].assign(&w.zr[0] + &w.zr[1]);
            oim[k].assign(&w.zi[0] + &w.zi[1]);
            ore[k + m].assign(&w.zr[0] - &w.zr[1]);
            oim[k + m].assign(&w.zi[0] - &w.zi[1]);
            continue;
        }
        if r == 3 {
            if let Some(s3) = &consts.s3 {
                butterfly3(w, s3, ore, oim, k, m);
                continue;
            }
        }
        if r == 5 {
            if let Some(c5) = &consts.c5 {
                butterfly5(w, c5, ore, oim, k, m);
                continue;
            }
        }
        for s in 0..r {
            w.acc_r.assign(&w.zr[0]);
            w.acc_i.assign(&w.zi[0]);
            for q in 1..r {
                w.a.assign(&w.zr[q]);
                w.b.assign(&w.zi[q]);
                rotate(
                    &mut w.a,
                    &mut w.b,
                    roots,
                    (q * s * m * scale) % roots.n,
                    &mut w.t,
                );
                w.acc_r += &w.a;
                w.acc_i += &w.b;
            }
            ore[k + s * m].assign(&w.acc_r);
            oim[k + s * m].assign(&w.acc_i);
        }
    }
}

/// The radix-3 butterfly on the twiddled z_0, z_1, z_2 of `w` into
/// out[k], out[k + m], out[k + 2m]: with t = z_1 + z_2, d = z_1 − z_2,
/// X_0 = z_0 + t, X_{1,2} = z_0 − t/2 ∓ i sin(2π/3) d (two real products
/// instead of the six complex ones of the plain sum).
fn butterfly3(w: &mut Work, s3: &Float, ore: &mut [Float], oim: &mut [Float], k: usize, m: usize) {
    let [tr, ti, dr, di, hr, hi, ..] = &mut w.v[..] else {
        unreachable!("16 scratch numbers")
    };
    let (zr, zi) = (&w.zr, &w.zi);
    tr.assign(&zr[1] + &zr[2]);
    ti.assign(&zi[1] + &zi[2]);
    dr.assign(&zr[1] - &zr[2]);
    di.assign(&zi[1] - &zi[2]);
    ore[k].assign(&zr[0] + &*tr);
    oim[k].assign(&zi[0] + &*ti);
    // h = z_0 − t/2
    *tr >>= 1;
    *ti >>= 1;
    hr.assign(&zr[0] - &*tr);
    hi.assign(&zi[0] - &*ti);
    // s·d
    *dr *= s3;
    *di *= s3;
    ore[k + m].assign(&*hr + &*di);
    oim[k + m].assign(&*hi - &*dr);
    ore[k + 2 * m].assign(&*hr - &*di);
    oim[k + 2 * m].assign(&*hi + &*dr);
}

/// The radix-5 butterfly on the twiddled z_0 … z_4 of `w` into
/// out[k + s m], s = 0..5: with a_1 = z_1 + z_4, a_2 = z_2 + z_3,
/// b_1 = z_1 − z_4, b_2 = z_2 − z_3 and c_j = cos(2πj/5), s_j = sin(2πj/5),
/// X_0 = z_0 + a_1 + a_2,
/// X_{1,4} = z_0 + c_1 a_1 + c_2 a_2 ∓ i(s_1 b_1 + s_2 b_2),
/// X_{2,3} = z_0 + c_2 a_1 + c_1 a_2 ∓ i(s_2 b_1 − s_1 b_2)
/// (16 real products instead of the 20 complex ones of the plain sum).
fn butterfly5(
    w: &mut Work,
    [c1, c2, s1, s2]: &[Float; 4],
    ore: &mut [Float],
    oim: &mut [Float],
    k: usize,
    m: usize,
) {
    let [a1r, a1i, a2r, a2i, b1r, b1i, b2r, b2i, xr, xi, yr, yi, t, ..] = &mut w.v[..] else {
        unreachable!("16 scratch numbers")
    };
    let (zr, zi) = (&w.zr, &w.zi);
    a1r.assign(&zr[1] + &zr[4]);
    a1i.assign(&zi[1] + &zi[4]);
    a2r.assign(&zr[2] + &zr[3]);
    a2i.assign(&zi[2] + &zi[3]);
    b1r.assign(&zr[1] - &zr[4]);
    b1i.assign(&zi[1] - &zi[4]);
    b2r.assign(&zr[2] - &zr[3]);
    b2i.assign(&zi[2] - &zi[3]);
    ore[k].assign(&zr[0] + &*a1r);
    ore[k] += &*a2r;
    oim[k].assign(&zi[0] + &*a1i);
    oim[k] += &*a2i;
    // (x, y) = (z_0 + c a_1 + c' a_2, s b_1 ± s' b_2); out[k + i m] = x − i y,
    // out[k + j m] = x + i y
    let mut pair =
        |c: &Float, cc: &Float, s: &Float, ss: &Float, minus: bool, i: usize, j: usize| {
            xr.assign(&*a1r * c);
            t.assign(&*a2r * cc);
            *xr += &*t;
            *xr += &zr[0];
            xi.assign(&*a1i * c);
            t.assign(&*a2i * cc);
            *xi += &*t;
            *xi += &zi[0];
            yr.assign(&*b1r * s);
            t.assign(&*b2r * ss);
            if minus {
                *yr -= &*t;
            } else {
                *yr += &*t;
            }
            yi.assign(&*b1i * s);
            t.assign(&*b2i * ss);
            if minus {
                *yi -= &*t;
            } else {
                *yi += &*t;
            }
            // x − i y = (x_r + y_i) + i(x_i − y_r)
            ore[k + i * m].assign(&*xr + &*yi);
            oim[k + i * m].assign(&*xi - &*yr);
            ore[k + j * m].assign(&*xr - &*yi);
            oim[k + j * m].assign(&*xi + &*yr);
        };
    pair(c1, c2, s1, s2, false, 1, 4);
    pair(c2, c1, s2, s1, true, 2, 3);
}

/// The DFT V_k = Σ_j v_j e^(−2πi jk/N) of N real values (N = the table's),
/// as (Re V, Im V) for k = 0..N: for even N by one complex transform of
/// length N/2 of z_j = v_{2j} + i v_{2j+1}, then
/// V_k = E_k + e^(−2πik/N) O_k, V_{k+N/2} = E_k − e^(−2πik/N) O_k with
/// E_k = (Z_k + conj Z_{N/2−k})/2, O_k = (Z_k − conj Z_{N/2−k})/2i.
pub(super) fn real_fft(v: Vec<Float>, roots: &Roots, p: u32) -> (Vec<Float>, Vec<Float>) {
    let n = v.len();
    if n % 2 == 1 {
        let mut re = v;
        let mut im = vec![Float::new(p); n];
        fft(&mut re, &mut im, roots, p);
        return (re, im);
    }
    let m = n / 2;
    let mut zr = Vec::with_capacity(m);
    let mut zi = Vec::with_capacity(m);
    let mut it = v.into_iter();
    while let (Some(a), Some(b)) = (it.next(), it.next()) {
        zr.push(a);
        zi.push(b);
    }
    fft(&mut zr, &mut zi, roots, p);
    let mut re = vec![Float::new(p); n];
    let mut im = vec![Float::new(p); n];
    let mut t = [Float::new(p), Float::new(p), Float::new(p)];
    let (mut er, mut ei, mut or, mut oi) =
        (Float::new(p), Float::new(p), Float::new(p), Float::new(p));
    for k in 0..m {
        let j = (m - k) % m;
        // E = (Z_k + conj Z_j)/2, O = (Z_k − conj Z_j)/2i
        er.assign(&zr[k] + &zr[j]);
        er >>= 1;
        ei.assign(&zi[k] - &zi[j]);
        ei >>= 1;
        // (Z_k − conj Z_j) = (zr_k − zr_j) + i(zi_k + zi_j); ÷ 2i: (a + ib)/2i = (b − ia)/2
        or.assign(&zi[k] + &zi[j]);
        or >>= 1;
        oi.assign(&zr[j] - &zr[k]);
        oi >>= 1;
        rotate(&mut or, &mut oi, roots, k, &mut t);
        re[k].assign(&er + &or);
        im[k].assign(&ei + &oi);
        re[k + m].assign(&er - &or);
        im[k + m].assign(&ei - &oi);
    }
    (re, im)
}
