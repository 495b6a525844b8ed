"""Drafting operations of the graphical method, on points as complex numbers [m].

Each function is one thing a draftsman does with compass and straightedge:
intersect two construction lines, swing two arcs, cut a line with an arc.
They raise :class:`~accelab.solver.errors.Singular` or
:class:`~accelab.solver.errors.NotAssemblable` instead of returning a point that the
drawing does not define.
"""

import math

from ..errors import NotAssemblable, Singular

#: Two construction lines whose directions differ by less than this angle
#: (sine of it) are treated as parallel: their intersection is not defined
#: well enough to read a value from (the analytic solver's toggle threshold).
PARALLEL_TOLERANCE = 1e-4


def cross(u, v):
    """z component of u x v for complex u, v."""
    return u.real * v.imag - u.imag * v.real


def dot(u, v):
    """Dot product of complex u, v taken as plane vectors."""
    return u.real * v.real + u.imag * v.imag


def unit(z):
    """z / |z| (z must not be zero)."""
    return z / abs(z)


def perpendicular(z):
    """z turned 90 degrees counter-clockwise (multiplication by j)."""
    return 1j * z


def component_along(z, direction):
    """Signed length of the projection of z on ``direction``."""
    return dot(z, direction) / abs(direction)


def intersect_lines(p1, u1, p2, u2, what="the construction lines"):
    """Intersection of the line through p1 along u1 with the line through p2 along u2.

    Returns ``(x, t1, t2)`` with x = p1 + t1 u1 = p2 + t2 u2.

    Raises
    ------
    Singular
        The lines are parallel (|sin of the angle between them| below
        :data:`PARALLEL_TOLERANCE`): the polygon does not close at one point.
    """
    den = cross(u1, u2)
    sin_angle = abs(den) / (abs(u1) * abs(u2))
    if not sin_angle >= PARALLEL_TOLERANCE:
        angle = math.degrees(math.asin(min(1.0, sin_angle)))
        raise Singular(
            f"{what} are parallel (angle between them {angle:.2g} deg): "
            "the polygon cannot be closed at this position (a toggle or limit "
            "position); move the input angle away from it",
            condition=sin_angle,
        )
    w = p2 - p1
    t1 = cross(w, u2) / den
    t2 = cross(w, u1) / den
    return p1 + t1 * u1, t1, t2


def intersect_circles(c1, r1, c2, r2, side, what="the links"):
    """Intersection of the circle (c1, r1) with the circle (c2, r2).

    ``side`` = +1 picks the point to the left of the line c1 -> c2 (counter-
    clockwise from it seen from c1), -1 the point to the right.

    Raises
    ------
    NotAssemblable
        The circles do not meet.
    """
    w = c2 - c1
    s = abs(w)
    if s == 0.0:
        raise NotAssemblable(f"{what}: the two arc centres coincide")
    # the triangle c1, c2, X: four times its area by the factored Heron form
    # (full relative accuracy as the triangle flattens), half chord h = 2 area / s
    prod = (s + r1 + r2) * (s + r1 - r2) * (s - r1 + r2) * (r1 + r2 - s)
    if prod < 0.0:
        raise NotAssemblable(
            f"{what} cannot close: arcs of radius {r1:.6g} m and {r2:.6g} m "
            f"about centres {s:.6g} m apart do not meet "
            f"(need |{r1:.4g} - {r2:.4g}| <= {s:.4g} <= {r1:.4g} + {r2:.4g})"
        )
    h = math.sqrt(prod) / (2.0 * s)
    x = (s * s + r1 * r1 - r2 * r2) / (2.0 * s)
    e = w / s
    return c1 + (x + 1j * side * h) * e


def intersect_line_circle(p, u, centre, r, sign, what="the link"):
    """Points p + t u (u a unit vector) at distance r from ``centre``.

    ``sign`` = +1 takes the larger t, -1 the smaller. Returns ``(x, t)``.

    Raises
    ------
    NotAssemblable
        The line misses the circle.
    """
    w = p - centre
    half_b = dot(w, u)
    dist = abs(cross(w, u))  # distance from the centre to the line
    h2 = (r - dist) * (r + dist)
    if h2 < 0.0:
        raise NotAssemblable(
            f"{what} cannot reach the line: the line passes "
            f"{dist:.6g} m from the centre, farther than the radius {r:.6g} m"
        )
    t = -half_b + sign * math.sqrt(h2)
    return p + t * u, t


def tip_to_tail(start, vectors):
    """Place ``vectors`` (complex) tip to tail from ``start``; returns the
    list of (tail, tip) pairs."""
    out = []
    tail = start
    for v in vectors:
        out.append((tail, tail + v))
        tail = tail + v
    return out
