//! A thin arithmetic wrapper over `rug::Float` so that the paper's formulas
//! read like the paper: `m2 * (g * c + r1 * s * phi1dd - r * thd.sq())`.
//!
//! Every operation rounds to nearest at the larger precision of its operands;
//! integers and rationals enter exactly. Nothing passes through `f64`.

use rug::{Float, Rational};
use std::ops::{Add, Div, Mul, Neg, Sub};

/// A real number at an explicit precision (a `Float` with operators).
#[derive(Clone, Debug, PartialEq, PartialOrd)]
pub struct X(pub Float);

impl X {
    /// The integer `n` at `prec` bits.
    pub fn int(prec: u32, n: i64) -> X {
        X(Float::with_val(prec, n))
    }

    /// The rational `q` rounded to `prec` bits.
    pub fn q(prec: u32, q: &Rational) -> X {
        X(Float::with_val(prec, q))
    }

    /// Precision in bits.
    pub fn prec(&self) -> u32 {
        self.0.prec()
    }

    /// 0 at this precision.
    pub fn zero(&self) -> X {
        X(Float::new(self.prec()))
    }

    /// The integer `n` at this precision.
    pub fn n(&self, n: i64) -> X {
        X::int(self.prec(), n)
    }

    /// sin.
    pub fn sin(&self) -> X {
        X(Float::with_val(self.prec(), self.0.sin_ref()))
    }

    /// cos.
    pub fn cos(&self) -> X {
        X(Float::with_val(self.prec(), self.0.cos_ref()))
    }

    /// arccos.
    pub fn acos(&self) -> X {
        X(Float::with_val(self.prec(), self.0.acos_ref()))
    }

    /// Square root.
    pub fn sqrt(&self) -> X {
        X(Float::with_val(self.prec(), self.0.sqrt_ref()))
    }

    /// |x|.
    pub fn abs(&self) -> X {
        X(Float::with_val(self.prec(), self.0.abs_ref()))
    }

    /// x².
    pub fn sq(&self) -> X {
        X(Float::with_val(self.prec(), self.0.square_ref()))
    }

    /// x³.
    pub fn cube(&self) -> X {
        self.sq() * self
    }

    /// The larger of two values.
    pub fn max(self, other: X) -> X {
        if other > self {
            other
        } else {
            self
        }
    }

    /// Whether the value is negative (and not zero).
    pub fn is_neg(&self) -> bool {
        self.0.is_sign_negative() && !self.0.is_zero()
    }

    /// A rounded `f64` for messages only.
    pub fn to_f64(&self) -> f64 {
        self.0.to_f64()
    }
}

macro_rules! binop {
    ($tr:ident, $m:ident, $op:tt) => {
        impl $tr<X> for X {
            type Output = X;
            fn $m(self, o: X) -> X {
                let p = self.prec().max(o.prec());
                X(Float::with_val(p, &self.0 $op &o.0))
            }
        }
        impl $tr<&X> for X {
            type Output = X;
            fn $m(self, o: &X) -> X {
                let p = self.prec().max(o.prec());
                X(Float::with_val(p, &self.0 $op &o.0))
            }
        }
        impl $tr<X> for &X {
            type Output = X;
            fn $m(self, o: X) -> X {
                let p = self.prec().max(o.prec());
                X(Float::with_val(p, &self.0 $op &o.0))
            }
        }
        impl $tr<&X> for &X {
            type Output = X;
            fn $m(self, o: &X) -> X {
                let p = self.prec().max(o.prec());
                X(Float::with_val(p, &self.0 $op &o.0))
            }
        }
        impl $tr<i32> for X {
            type Output = X;
            fn $m(self, o: i32) -> X {
                let p = self.prec();
                X(Float::with_val(p, &self.0 $op o))
            }
        }
        impl $tr<i32> for &X {
            type Output = X;
            fn $m(self, o: i32) -> X {
                let p = self.prec();
                X(Float::with_val(p, &self.0 $op o))
            }
        }
        impl $tr<X> for i32 {
            type Output = X;
            fn $m(self, o: X) -> X {
                let p = o.prec();
                X(Float::with_val(p, self $op &o.0))
            }
        }
        impl $tr<&X> for i32 {
            type Output = X;
            fn $m(self, o: &X) -> X {
                let p = o.prec();
                X(Float::with_val(p, self $op &o.0))
            }
        }
    };
}

binop!(Add, add, +);
binop!(Sub, sub, -);
binop!(Mul, mul, *);
binop!(Div, div, /);

impl Neg for X {
    type Output = X;
    fn neg(self) -> X {
        X(-self.0)
    }
}

impl Neg for &X {
    type Output = X;
    fn neg(self) -> X {
        X(Float::with_val(self.prec(), -&self.0))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arithmetic_is_exact_where_it_should_be() {
        let a = X::int(128, 3);
        let b = X::q(128, &Rational::from((1, 3)));
        let one = &a * &b;
        assert_eq!(X(Float::with_val(128, 1u32)), (one.clone() - 1i32) + 1i32);
        assert_eq!((2i32 - &a).to_f64(), -1.0);
        assert_eq!((-&a).to_f64(), -3.0);
        assert_eq!(a.cube().to_f64(), 27.0);
        assert_eq!((1i32 / X::int(64, 4)).to_f64(), 0.25);
    }
}
