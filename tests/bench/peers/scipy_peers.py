#!/usr/bin/python3
"""Kontur beside numpy/scipy (issue 21), on 10^6 points in one run, best against best.

Run by hand where python3-scipy is installed: tests/bench/peers/scipy_peers.py [path/to/kontur-cli]
(default build/src/cli/kontur-cli). The natural spline through the points with chord-length
parameters (scipy CubicSpline) and the least-squares cubic Bézier of the points (numpy lstsq on the
Bernstein matrix), against `kontur-cli bench spline-natural` and `bench fit-ls` with the same N.
OPENBLAS_CORETYPE and OPENBLAS_L2_SIZE are unset for numpy's side: they slow a current numpy.
"""
import json
import os
import subprocess
import sys
import time

for name in ("OPENBLAS_CORETYPE", "OPENBLAS_L2_SIZE"):
    os.environ.pop(name, None)

import numpy as np  # noqa: E402  (after the environment is set)
from scipy.interpolate import CubicSpline  # noqa: E402

N = 1_000_000
ROUNDS = 5
cli = sys.argv[1] if len(sys.argv) > 1 else os.path.join("build", "src", "cli", "kontur-cli")


def best(fn):
    times = []
    for _ in range(ROUNDS):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return min(times) * 1e3


rng = np.random.default_rng(2024)
# A random walk, as Kontur's spline bench uses, and a noisy wavy arc for the fit.
pts = np.cumsum(rng.uniform(-1.0, 1.0, size=(N, 2)) + np.array([1.0, 0.0]), axis=0)


def natural():
    chord = np.concatenate(([0.0], np.cumsum(np.hypot(*np.diff(pts, axis=0).T))))
    return CubicSpline(chord, pts, bc_type="natural")


u = np.linspace(0.0, 1.0, N)
arc = np.column_stack((100.0 * u, 30.0 * np.sin(3.0 * u))) + rng.normal(0.0, 1.0, size=(N, 2))


def least_squares():
    chord = np.concatenate(([0.0], np.cumsum(np.hypot(*np.diff(arc, axis=0).T))))
    s = chord / chord[-1]
    v = 1.0 - s
    basis = np.column_stack((v ** 3, 3 * s * v * v, 3 * s * s * v, s ** 3))
    return np.linalg.lstsq(basis, arc, rcond=None)[0]


def kontur(op):
    out = subprocess.run([cli, "bench", op, "--n", str(N), "--repeat", str(ROUNDS)], check=True,
                         capture_output=True, text=True).stdout
    return json.loads(out.strip().splitlines()[-1])["min_ns"] / 1e6


scipy_ms = best(natural)
numpy_ms = best(least_squares)
kontur_spline = kontur("spline-natural")
kontur_fit = kontur("fit-ls")
print(f"natural spline through 10^6 points (chord): Kontur {kontur_spline:7.1f} ms, "
      f"scipy CubicSpline {scipy_ms:7.1f} ms, {scipy_ms / kontur_spline:4.1f}x")
print(f"least-squares cubic of 10^6 points:        Kontur {kontur_fit:7.1f} ms, "
      f"numpy lstsq {numpy_ms:7.1f} ms, {numpy_ms / kontur_fit:4.1f}x")
