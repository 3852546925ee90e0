"""Numbers as the tables print them when no format spec is given."""

import math


def plain_number(x):
    """In as few digits as give the number back: 1108, 0.06, 1e-07 (integers without '.0')."""
    if isinstance(x, bool):
        raise TypeError("a boolean is not a number")
    if isinstance(x, int):
        return str(x)
    if math.isfinite(x) and x == math.trunc(x) and abs(x) < 1e17:
        return str(int(x))
    return repr(x)


def round_half_away(x):
    """x rounded to an integer, halves away from zero (C's round, not Python's half-even)."""
    t = math.trunc(x)
    if abs(x - t) >= 0.5:  # exact: a double minus its integer part
        t += math.copysign(1, x)
    return float(t)


def short(x, digits):
    """x rounded half away from zero to `digits` decimals, in as few digits as it needs: short(0.0601, 3)
    is 0.06, short(1108.04, 1) is 1108."""
    scale = 10 ** digits
    return plain_number(round_half_away(x * scale) / scale)
