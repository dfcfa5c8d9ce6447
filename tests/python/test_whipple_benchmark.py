"""The benchmark bicycle from Python against the published benchmark: Meijaard, Papadopoulos, Ruina,
Schwab (2007), "Linearized dynamics equations for the balance and steer of a bicycle: a benchmark and
review", Proc. R. Soc. A 463:1955-1982: Table 2 (eigenvalues at 0-10 m/s, weave and capsize speeds)
and Appendix A (the matrices M, C1, K0, K2 of M q'' + v C1 q' + (g K0 + v^2 K2) q = 0, q = (roll, steer))."""
import random

import numpy as np
import pytest

from conftest import WHIPPLE

# Table 2: v (m/s), weave (one member of the pair; at 0 m/s the two real roots), capsize, castor.
TABLE2 = [
    (0, 3.13164324790656 + 0j, 5.53094371765393 + 0j, -3.13164324790656, -5.53094371765393),
    (1, 3.52696170990070 + 0.80774027519930j, None, -3.13423125066578, -7.11008014637442),
    (2, 2.68234517512745 + 1.68066296590675j, None, -3.07158645641514, -8.67387984831735),
    (3, 1.70675605663975 + 2.31582447384325j, None, -2.63366137253667, -10.35101467245920),
    (4, 0.41325331521125 + 3.07910818603206j, None, -1.42944427361326, -12.15861426576450),
    (5, -0.77534188219585 + 4.46486771378823j, None, -0.32286642900409, -14.07838969279820),
    (6, -1.52644486584142 + 5.87673060598709j, None, -0.00406690076970, -16.08537123098030),
    (7, -2.13875644258362 + 7.19525913329805j, None, 0.10268170574766, -18.15788466125262),
    (8, -2.69348683581097 + 8.46037971396931j, None, 0.14327879765713, -20.27940894394569),
    (9, -3.21675402252485 + 9.69377351531791j, None, 0.15790184030917, -22.43788559040858),
    (10, -3.72016840437287 + 10.90681139476287j, None, 0.16105338653172, -24.62459635017404),
]
WEAVE_SPEED = 4.29238253634111    # Table 2, m/s
CAPSIZE_SPEED = 6.02426201538837  # Table 2, m/s

# Appendix A (with g = 9.81 m/s^2).
M = np.array([[80.81722, 2.31941332208709], [2.31941332208709, 0.29784188199686]])
C1 = np.array([[0, 33.86641391492494], [-0.85035641456978, 1.68540397397560]])
K0 = np.array([[-80.95, -2.59951685249872], [-2.59951685249872, -0.80329488458618]])
K2 = np.array([[0, 76.59734589573222], [0, 2.65431523794604]])


def benchmark_eigenvalues(v, g=9.81):
    """The four eigenvalues of the benchmark's linear equations at speed v, computed here."""
    Minv = np.linalg.inv(M)
    A = np.block([[np.zeros((2, 2)), np.eye(2)], [-Minv @ (g * K0 + v * v * K2), -Minv @ (v * C1)]])
    return np.linalg.eigvals(A)


@pytest.fixture(scope="module")
def sweep(motostab):
    return motostab.sweep(motostab.Scenario.load(WHIPPLE), speeds=(0, 10, 0.5))


def nearest(values, target):
    return values[np.argmin(np.abs(values - target))]


def test_table2_eigenvalues_and_labels(sweep):
    for v, weave, weave2, capsize, castor in TABLE2:
        k = int(np.flatnonzero(sweep.speeds == v)[0])
        ev, labels = sweep.eigenvalues[k], sweep.labels[k]
        for expected, label in ((weave, "weave"), (weave2, "weave"), (capsize, "capsize"), (castor, "castor")):
            if expected is None:
                continue
            mine = ev[labels == label]
            assert len(mine) > 0, (v, label)
            assert abs(nearest(mine, expected) - expected) < 1e-8, (v, label, nearest(mine, expected), expected)
        if weave.imag > 0:  # the pair: both members labelled weave
            assert abs(nearest(ev[labels == "weave"], weave.conjugate()) - weave.conjugate()) < 1e-8


def test_table2_critical_speeds(sweep):
    found = {(c.mode, c.direction): c.speed_mps for c in sweep.critical_speeds}
    assert found[("weave", "stabilising")] == pytest.approx(WEAVE_SPEED, abs=1e-8)
    assert found[("capsize", "destabilising")] == pytest.approx(CAPSIZE_SPEED, abs=1e-8)
    # Stable between the weave and the capsize speeds (Meijaard et al. 2007, sec. 6).
    assert sweep.stable_ranges.shape == (1, 2)
    assert sweep.stable_ranges[0] == pytest.approx([WEAVE_SPEED, CAPSIZE_SPEED], abs=1e-8)


def test_linearize_at_random_speeds_against_appendix_a(motostab):
    bike = motostab.Scenario.load(WHIPPLE)
    rng = random.Random(2007)
    for v in (rng.uniform(0.3, 10) for _ in range(4)):
        lin = motostab.linearize(bike, v)
        assert lin.speed_mps == v and lin.A.shape == (len(lin.state_names),) * 2
        for expected in benchmark_eigenvalues(v):
            assert abs(nearest(lin.eigenvalues, expected) - expected) < 1e-7 * max(1, abs(expected)), (v, expected)
        # Each eigenvector satisfies A x = lambda x.
        for k in range(len(lin.eigenvalues)):
            x = lin.eigenvectors[:, k]
            assert np.linalg.norm(lin.A @ x - lin.eigenvalues[k] * x) < 1e-9 * max(1, abs(lin.eigenvalues[k]))
