#!/usr/bin/env python3
"""Independent reader of motostab's linear_models.mat (SciPy's loadmat), for the tests.

    read_linear_models.py MAT EIGENVALUES_CSV sweep|linearize [A_CSV]

Checks the variables' shapes and names, that speeds_mps (and roll_rad) give the points of
EIGENVALUES_CSV, and that the eigenvalues of each A(:, :, k) (numpy.linalg.eigvals) equal the CSV's
at that point; with A_CSV (linearize) also that state_names are A.csv's rows and A equals it.
Exit status 0 when every check holds; the first failure is printed.
"""
import csv
import sys

import numpy as np
import scipy.io


def fail(message):
    print("read_linear_models: " + message)
    sys.exit(1)


def names(cell):
    return [str(np.asarray(c).ravel()[0]) if np.asarray(c).size else "" for c in np.asarray(cell).ravel()]


def match(got, expected, scale):
    """Each expected eigenvalue has its own computed one within 1e-9 of the matrix scale."""
    got = list(got)
    for e in expected:
        k = min(range(len(got)), key=lambda i: abs(got[i] - e))
        if abs(got[k] - e) > 1e-9 * scale:
            return "eigenvalue %r: nearest of A's is %r" % (e, got[k])
        got.pop(k)
    return None


def main():
    mat, eig_csv, kind = sys.argv[1], sys.argv[2], sys.argv[3]
    m = scipy.io.loadmat(mat)
    for key in ("A", "B", "speeds_mps", "roll_rad", "state_names", "input_names"):
        if key not in m:
            fail("no variable " + key)
    states, inputs = names(m["state_names"]), names(m["input_names"])
    A, B = m["A"], m["B"]
    n, K = len(states), m["speeds_mps"].size
    A = A.reshape(n, n, K, order="F") if A.ndim == 2 else A
    B = B.reshape(n, len(inputs), K, order="F") if B.ndim == 2 else B
    if A.shape != (n, n, K) or B.shape != (n, len(inputs), K) or m["roll_rad"].size != K:
        fail("shapes A %s, B %s, %d states, %d inputs, %d speeds" % (A.shape, B.shape, n, len(inputs), K))
    with open(eig_csv) as f:
        rows = list(csv.DictReader(f))
    speeds = m["speeds_mps"].ravel()
    for k in range(K):
        if kind == "sweep":
            at = [r for r in rows if float(r["speed_mps"]) == speeds[k]]
        else:
            at = rows
        expected = [complex(float(r["real"]), float(r["imag"])) for r in at]
        if len(expected) != n:
            fail("speed %r: %d eigenvalues in the CSV, %d states" % (speeds[k], len(expected), n))
        why = match(np.linalg.eigvals(A[:, :, k]), expected, max(1.0, np.abs(A[:, :, k]).max()))
        if why:
            fail("speed %r: %s" % (speeds[k], why))
    if len(sys.argv) > 4:
        with open(sys.argv[4]) as f:
            table = list(csv.reader(f))
        if [r[0] for r in table[1:]] != states or table[0][1:] != states:
            fail("state_names differ from A.csv's: %s" % states)
        if not np.array_equal(np.array([[float(v) for v in r[1:]] for r in table[1:]]), A[:, :, 0]):
            fail("A differs from A.csv")
    print("read_linear_models: %d models, %d states, %d inputs (%s): ok" % (K, n, len(inputs), ", ".join(inputs)))


if __name__ == "__main__":
    main()
