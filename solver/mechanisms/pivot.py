"""What a refusal says where the crank pin A passes over the pivot O4.

There link 4's direction is 0/0 and the kernels refuse the derivatives they cannot vouch
for (:func:`accelab.solver.kernels.common.over_the_pivot`); A can come that near O4 only
where a = d (and, in a fourbar, b = c: a kite). The generic advice, to move theta2 about
1e-6 rad, is not enough there: about 1e-3 of the lengths' sum is.
"""

import numpy as np

from ..kernels.common import pivot_fraction

#: |A - O4| / span below which a jerk is refused
FRACTION = pivot_fraction(3)


def near(a, d, theta1, theta2, span):
    """|A - O4| [m] where A is within the refused reach of O4, else None."""
    t = theta2 - theta1
    s = float(np.hypot(a * np.cos(t) - d, a * np.sin(t)))
    return s if s < span * FRACTION else None


def reason(shown, equal):
    """Why: ``shown`` is |A - O4| as the mechanism shows lengths; ``equal`` the lengths
    that are (nearly) equal, e.g. "a = d"."""
    return (
        f"the crank pin A passes {shown} from the pivot O4 ({equal}), where link 4's "
        f"direction is undefined and each derivative divides by |A - O4| again"
    )


def advice(a, span, equal):
    """How far to move: theta2 from theta1 [rad], or the lengths apart (as a share of
    ``span``, the sum of the mechanism's lengths)."""
    return (
        f"Keep theta2 at least about {span * FRACTION / a:.0e} rad from theta1 (A is over O4 "
        f"there), or make {equal} differ by more than {FRACTION:.0e} of the lengths' sum"
    )
