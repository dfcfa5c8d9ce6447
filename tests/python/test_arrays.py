"""Results as NumPy arrays that own the C++ buffers (no copy), the GIL released while motostab
computes, and threads= as on the command line."""
import threading

import numpy as np
import pytest

from conftest import ENDURO, WHIPPLE


def owns_cxx_buffer(array):
    """A view of a buffer the extension handed over (its base is the capsule that frees it)."""
    return not array.flags.owndata and type(array.base).__name__ == "PyCapsule"


def test_arrays_view_the_computed_buffers(motostab):
    bike = motostab.Scenario.load(WHIPPLE)
    lin = motostab.linearize(bike, 4.5)
    for a in (lin.A, lin.B, lin.eigenvalues, lin.eigenvectors):
        assert owns_cxx_buffer(a)
    assert lin.A.flags.f_contiguous and lin.eigenvalues.dtype == np.complex128
    sweep = motostab.sweep(bike, speeds=(0, 2, 0.5))
    assert owns_cxx_buffer(sweep.speeds) and owns_cxx_buffer(sweep.eigenvalues) and owns_cxx_buffer(sweep.A)
    assert sweep.eigenvalues.shape == sweep.labels.shape == (5, sweep.eigenvalues.shape[1])
    assert sweep.branch_labels.shape == (sweep.eigenvalues.shape[1],)  # one per tracked root
    assert sweep.A.shape == (5, len(sweep.state_names), len(sweep.state_names))
    sim = motostab.simulate(bike, 5, 0.2, perturb=["roll-rate:0.1"])
    assert owns_cxx_buffer(sim.samples)
    assert np.shares_memory(sim["roll_rate"], sim.samples) and np.shares_memory(sim.time, sim.samples)


def test_the_gil_is_released_during_a_sweep(motostab):
    enduro = motostab.Scenario.load(ENDURO)
    done = threading.Event()
    worker = threading.Thread(target=lambda: (motostab.sweep(enduro, speeds=(0, 40, 0.5)), done.set()))
    ticks = 0
    worker.start()
    while not done.is_set() and worker.is_alive():
        ticks += 1  # runs only while the sweep does not hold the GIL
    worker.join()
    assert done.is_set()
    assert ticks > 1000


def test_threads_as_on_the_command_line(motostab):
    enduro = motostab.Scenario.load(ENDURO).with_(**{"swingarm.compliance": "twist"})
    one = motostab.sweep(enduro, speeds=(1, 40, 1))
    two = motostab.sweep(enduro, speeds=(1, 40, 1), threads=2)
    assert np.array_equal(one.speeds, two.speeds) and np.array_equal(one.labels, two.labels)
    # Threaded sweeps agree with the serial one to the trim tolerance (analysis/sweep.h), not to the bit.
    scale = np.maximum(1, np.abs(one.eigenvalues))
    assert np.max(np.abs(one.eigenvalues - two.eigenvalues) / scale) < 1e-7
    assert [c.mode for c in one.critical_speeds] == [c.mode for c in two.critical_speeds]
