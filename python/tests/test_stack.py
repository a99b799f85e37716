"""Stacks of bonded layers from Python: merging, and the solver against the
exact axisymmetric stiffness of a three-layer stack."""

import pytest

import layered_contact as lc

HARD = lc.Material(20e6, 0.3)
SOFT = lc.Material(1e6, 0.49)


def test_stacks_merge_and_report_their_layers():
    stack = lc.Substrate.stack([(SOFT, 1e-3), (HARD, 0.5e-3), (SOFT, 2e-3)])
    assert stack.layer_count == 3
    assert stack.total_thickness == pytest.approx(3.5e-3, rel=1e-15)
    merged = lc.Substrate.stack([(SOFT, 1e-3), (SOFT, 2e-3)], HARD)
    assert merged.layer_count == 1
    assert merged.total_thickness == 3e-3
    assert lc.Substrate.stack([], HARD).layer_count == 0
    with pytest.raises(lc.InvalidInputError, match="thickness"):
        lc.Substrate.stack([(SOFT, -1e-3), (HARD, 1e-3)])


def test_punch_on_a_stack_matches_the_exact_stiffness():
    # 64 cells across a 1.5 mm punch on soft/hard/soft over a rigid base:
    # the Rust suite measures -0.31 % at 128 cells; the error halves per
    # doubling (1/N), so about -0.6 % here.
    stack = lc.Substrate.stack([(SOFT, 1e-3), (HARD, 0.5e-3), (SOFT, 2e-3)])
    a, across, d = 1.5e-3, 64, 1e-6
    solver = lc.ContactSolver(stack, across + 2, across + 2, 2 * a / across)
    s = solver.solve_depth(lc.Indenter.flat_punch(a), d)
    exact = lc.analytic.flat_punch_stiffness(stack, s.contact_radius)
    assert s.force / d == pytest.approx(exact, rel=0.01)
