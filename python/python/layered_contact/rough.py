"""What rough-contact studies read off a periodic contact along a force
protocol: the contact fraction, the mean gap and the interfacial stiffness
against the mean pressure, and the gaps themselves."""

from __future__ import annotations

from typing import Any, Dict, Sequence

import numpy as np

from ._native import ContactSolver, Indenter, InvalidInputError


def interface_curve(
    solver: ContactSolver, indenter: Indenter, mean_pressures: Sequence[float]
) -> Dict[str, Any]:
    """Solve ``indenter`` on ``solver`` (a periodic grid, or any grid the
    indenter covers) at each mean pressure (Pa, increasing, each solve
    warm-started from the last) and return a dict of arrays:
    ``mean_pressure`` (Pa), ``contact_fraction``, ``mean_gap`` (m, the mean
    separation ``u_bar`` of `Solution.mean_gap`), ``stiffness`` (the
    interfacial stiffness ``-dp/du_bar``, Pa/m, by central differences of
    neighbouring loads, one-sided at the ends; Persson 2007, Phys. Rev. Lett.
    99, 125502) and ``gaps`` (the gap field at each load, for its
    distribution). Checked against Westergaard's wavy surface
    (``tests/test_solver.py``)."""
    pressures = np.asarray(mean_pressures, dtype=np.float64)
    if pressures.ndim != 1 or pressures.size < 2:
        raise InvalidInputError(
            f"mean_pressures: {pressures.size} values; expected at least two, in order")
    if not (np.all(np.isfinite(pressures)) and np.all(pressures > 0.0)
            and np.all(np.diff(pressures) > 0.0)):
        raise InvalidInputError(
            f"mean_pressures {pressures}: expected positive, finite and increasing (Pa)")
    rows, columns, spacing = solver.grid
    area = rows * columns * spacing**2
    fractions, gaps, fields = [], [], []
    for k, pressure in enumerate(pressures):
        solution = solver.solve_force(indenter, pressure * area, warm_start=k > 0)
        if solution.mean_gap is None:
            raise InvalidInputError(
                "the indenter does not cover the grid (infinite gaps): no mean gap")
        fractions.append(solution.contact_area / area)
        gaps.append(solution.mean_gap)
        fields.append(solution.gap)
    mean_gap = np.asarray(gaps)
    return {
        "mean_pressure": pressures,
        "contact_fraction": np.asarray(fractions),
        "mean_gap": mean_gap,
        "stiffness": -np.gradient(pressures, mean_gap),
        "gaps": fields,
    }
