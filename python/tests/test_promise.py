"""Issue 24: Ctrl-C stops a run, and arrays are checked before they are copied."""

import _thread
import signal
import threading

import numpy as np
import pytest

import layered_contact as lc

# A force cycle of 100 000 steps on a small grid: about 50 s to its end.
LONG = {
    "substrate": {"kind": "half_space", "youngs_modulus": 1e6, "poisson_ratio": 0.5},
    "indenter": {"kind": "paraboloid", "radius": 1e-2},
    "protocol": {"kind": "force_cycle", "max_force": 1e-3, "steps": 100000},
    "resolution": {"cells_across": 16},
}


def test_ctrl_c_stops_a_run_within_a_few_steps():
    steps = []
    # Ctrl-C once the run is under way (the first step has been reported).
    started = threading.Event()
    threading.Thread(target=lambda: started.wait(60) and _thread.interrupt_main(), daemon=True).start()

    def progress(step):
        steps.append(step)
        started.set()

    # Python keeps SIGINT ignored when its parent ignored it (a background
    # job of a shell without job control); Ctrl-C and interrupt_main then do
    # nothing, so the test installs Python's own handler for its run.
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        with pytest.raises(KeyboardInterrupt):
            lc.run_scene(LONG, progress=progress)
    finally:
        signal.signal(signal.SIGINT, previous)
    # It used to run all 200 001 steps before raising.
    assert 1 <= len(steps) < 100000


def test_broadcast_arrays_are_refused_before_they_are_copied():
    huge = np.broadcast_to(np.zeros(1), (1, 2**31))
    with pytest.raises(lc.InvalidInputError, match="2\\^15 cells per axis"):
        lc.Indenter.height_map(huge, 1e-4)
    rubber = lc.Material(1e6, 0.5)
    with pytest.raises(lc.InvalidInputError, match="at most 2\\^27 values"):
        lc.analytic.hertz_force(rubber, 1e-2, np.broadcast_to(np.zeros(1), (2**31,)))
    with pytest.raises(lc.InvalidInputError, match="at most 2\\^27 values"):
        lc.Indenter.sphere(1e-2).height(huge, huge)
