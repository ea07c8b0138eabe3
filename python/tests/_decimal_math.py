"""Just enough high-precision arithmetic for the tests (no mpmath needed)."""
from decimal import Decimal, localcontext


def pi(prec):
    """π to `prec` digits (Machin: π = 16 atan(1/5) − 4 atan(1/239))."""
    with localcontext() as c:
        c.prec = prec + 10

        def atan_inv(n):
            x = Decimal(1) / n
            x2 = x * x
            s, term, k = Decimal(0), x, 0
            while term != 0:
                s += term / (2 * k + 1) * (-1 if k % 2 else 1)
                term *= x2
                k += 1
                if abs(term) < Decimal(10) ** (-(prec + 10)):
                    break
            return s

        return +(16 * atan_inv(5) - 4 * atan_inv(239))


def cos(x, prec):
    with localcontext() as c:
        c.prec = prec + 10
        x = Decimal(x)
        s, term, k = Decimal(1), Decimal(1), 0
        while True:
            term = -term * x * x / ((2 * k + 1) * (2 * k + 2))
            k += 1
            if abs(term) < Decimal(10) ** (-(prec + 8)):
                break
            s += term
        return +s


def round_sig(x, digits):
    """`x` rounded to `digits` significant digits, as text the way cylroll prints it."""
    with localcontext() as c:
        c.prec = digits
        return format(+Decimal(x), "f")
