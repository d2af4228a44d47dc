"""Two horizontal components of a record applied at an incidence angle.

A record's two horizontal components are recorded along two orthogonal directions of the
station (for example 180 = N–S and 270 = E–W). Applied to a site whose axes x and y are the
buildings' (x across the gap), at an angle α between the first component and the site x
axis (counter-clockwise), the site components are the rotation (Boore 2010, BSSA 100(4),
1830–1835, eq 1, for the rotated components of RotD spectra; Chopra §9.5.2 for the
equations of motion under both components together)

    a_x(t) = a_1(t) cos α − a_2(t) sin α,
    a_y(t) = a_1(t) sin α + a_2(t) cos α.

One component alone (``a_2 = 0``) at α shakes along the direction α.
"""

from __future__ import annotations

import numpy as np

from pounding.ground_motion.motion import GroundMotion
from pounding.units import direction_cosines

__all__ = ["at_incidence"]


def at_incidence(first: GroundMotion, second: GroundMotion | None = None,
                 angle: float = 0.0) -> tuple[GroundMotion, GroundMotion]:
    """The site x and y ground accelerations of one or two horizontal record components.

    Parameters
    ----------
    first : GroundMotion
        The first horizontal component [m/s²], along the direction ``angle``.
    second : GroundMotion, optional
        The second horizontal component, orthogonal to the first (at ``angle + 90°``); none:
        the first component alone.
    angle : float
        Incidence angle α [degrees] of the first component from the site x axis,
        counter-clockwise, in [-360, 360]. Exact at multiples of 90° (0°: the first
        component along x).

    Returns
    -------
    (GroundMotion, GroundMotion)
        ``a_x`` and ``a_y`` [m/s²] on the first component's time step; the shorter component
        is taken as zero after its end.

    Raises
    ------
    ValueError
        The two components have different time steps, or the angle is not a number in
        [-360, 360].

    Examples
    --------
    >>> from pounding.ground_motion import harmonic
    >>> a1 = harmonic(1.0, 1.0, duration=2.0, dt=0.01)
    >>> ax, ay = at_incidence(a1, angle=90.0)
    >>> float(abs(ax.accel).max()), bool(np.array_equal(ay.accel, a1.accel))
    (0.0, True)
    """
    if not isinstance(first, GroundMotion):
        raise ValueError(f"first: expected a GroundMotion (got {type(first).__name__})")
    if second is not None and not isinstance(second, GroundMotion):
        raise ValueError(f"second: expected a GroundMotion or None (got "
                         f"{type(second).__name__})")
    try:
        c, s = direction_cosines(float(angle))
    except (TypeError, ValueError):
        raise ValueError(f"angle must be a number of degrees in [-360, 360] (got "
                         f"{angle!r})") from None
    a1 = first.accel
    if second is None:
        a2 = np.zeros_like(a1)
        name = f"{first.name} at {float(angle):g}°"
    else:
        if second.dt != first.dt:
            raise ValueError(f"second: its time step {second.dt:g} s differs from the first "
                             f"component's {first.dt:g} s; resample one of them")
        n = max(a1.size, second.accel.size)
        a1 = np.concatenate([a1, np.zeros(n - a1.size)])
        a2 = np.concatenate([second.accel, np.zeros(n - second.accel.size)])
        name = f"{first.name} + {second.name} at {float(angle):g}°"
    meta = {"components": [first.name] + ([second.name] if second is not None else []),
            "incidence_deg": float(angle)}
    ax = GroundMotion(first.dt, c * a1 - s * a2, name=f"{name} (x)", source=first.source,
                      units_read=first.units_read, metadata={**meta, "axis": "x"})
    ay = GroundMotion(first.dt, s * a1 + c * a2, name=f"{name} (y)", source=first.source,
                      units_read=first.units_read, metadata={**meta, "axis": "y"})
    return ax, ay
