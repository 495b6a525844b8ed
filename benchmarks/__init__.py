"""The speed-against-accuracy benchmark (``accelab bench``, ``make bench``).

It sits beside the library, not in it: it measures :mod:`accelab.solver` from the
outside and needs mpmath (``pip install -e ".[bench]"``), which a plain
install of the library does not. Nothing imports mpmath until a run starts
(:mod:`.cli` checks first and says what to install).

:mod:`.cases` is the documented set of linkages, :mod:`.reference` their
high-precision (mpmath) solution, :mod:`.methods` the ways of computing the
same kinematics that are compared (closed forms unit-free and unit-aware, a
scalar loop, the general vector-loop solver, finite differences, the
graphical construction, peer packages when installed), :mod:`.timing` the
clock, :mod:`.stability` the study near toggle positions, :mod:`.scaling`
how cost grows, :mod:`.charts` the figures and :mod:`.run` the whole run.
"""
