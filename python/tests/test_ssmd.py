# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Tests of the Python package ssmd: agreement with the C++ API, analytic
spectra, exact handles, clear exceptions, the basis cache, the progress
callback, the GIL and reference counts."""

import gc
import os
import subprocess
import sys
import threading
import tracemalloc
import warnings

import numpy as np
import pytest

import ssmd
from conftest import icosphere, tube


def reference_deformation(V, F, roi, handles, targets, algorithm, policy, m, iterations, tolerance):
    """The same deformation through the C++ API (tests/reference_deformation.cpp)."""
    program = os.environ.get("SSMD_PYTHON_REFERENCE")
    if not program:
        pytest.skip("SSMD_PYTHON_REFERENCE is not set (run through ctest)")
    lines = ["%d %d" % (len(V), len(F))]
    lines += ["%r %r %r" % tuple(p) for p in V.tolist()]
    lines += ["%d %d %d" % tuple(f) for f in F.tolist()]
    lines += [str(len(roi)), " ".join(map(str, roi))]
    lines += [str(len(handles)), " ".join(map(str, handles))]
    lines += ["%r %r %r" % tuple(p) for p in targets.tolist()]
    lines += ["%s %s %d %d %r" % (algorithm, policy, m, iterations, tolerance)]
    out = subprocess.run([program], input="\n".join(lines) + "\n", capture_output=True, text=True,
                         check=True).stdout
    return np.array([[float(x) for x in line.split()] for line in out.splitlines()])


def bent_targets(V, handles):
    """The top ring moved sideways and turned by 40 degrees about x."""
    a = np.radians(40)
    R = np.array([[1, 0, 0], [0, np.cos(a), -np.sin(a)], [0, np.sin(a), np.cos(a)]])
    P = V[handles]
    c = P.mean(axis=0)
    return (P - c) @ R.T + c + np.array([0.0, 0.8, -0.3])


@pytest.mark.parametrize("algorithm,policy", [("spectral", "exact"), ("spectral", "soft"),
                                              ("linear", "exact"), ("spatial", "exact")])
def test_same_result_as_the_cpp_api(tube_mesh, algorithm, policy):
    V, F, fixed, handles = tube_mesh
    roi = np.setdiff1d(np.arange(len(V)), fixed)
    targets = bent_targets(V, handles)
    d = ssmd.Deformation(V, F, roi=roi, handles=handles, m=30, policy=policy, algorithm=algorithm)
    d.set_targets(targets)
    W = d.deform(iterations=6, tolerance=0.0)
    expected = reference_deformation(V, F, roi, handles, targets, algorithm, policy, 30, 6, 0.0)
    assert W.shape == V.shape
    assert np.max(np.abs(W - expected)) <= 1e-12


def test_rotation_patches(tube_mesh):
    """One patch per dual vertex is the full iteration; more patches come closer to it."""
    V, F, fixed, handles = tube_mesh
    targets = bent_targets(V, handles)

    def run(patches):
        d = ssmd.Deformation(V, F, fixed=fixed, handles=handles, m=30, rotation_patches=patches)
        d.set_targets(targets)
        return d.deform(iterations=6, tolerance=0.0)

    full = run(0)
    diagonal = np.linalg.norm(V.max(axis=0) - V.min(axis=0))
    assert np.max(np.abs(run(10**9) - full)) <= 1e-9 * diagonal
    few = np.max(np.linalg.norm(run(20) - full, axis=1))
    # 200 patches of the tube's 960 faces: several faces each, so that the
    # library keeps the patches rather than going back to the full iteration
    # on patches of one or two faces.
    many = np.max(np.linalg.norm(run(200) - full, axis=1))
    assert 0 < many < few < 0.2 * diagonal
    expect_value_error("rotation_patches", lambda: ssmd.Deformation(V, F, fixed=fixed, handles=handles,
                                                                    rotation_patches=-1))


def test_stage_angle(tube_mesh):
    """A turn of 40 degrees takes two stages of at most 30 (the default), small changes one; 0 is one stage."""
    V, F, fixed, handles = tube_mesh
    targets = bent_targets(V, handles)

    def run(**settings):
        d = ssmd.Deformation(V, F, fixed=fixed, handles=handles, m=30, **settings)
        d.set_targets(targets)
        W = d.deform(iterations=6, tolerance=0.0)
        assert np.max(np.abs(W[handles] - targets)) <= 1e-9
        return W, d

    staged, d = run(stage_angle=30)
    assert d.deform_report["stages"] == 2
    d.set_targets(targets + np.array([0.0, 0.01, 0.0]))
    d.deform(iterations=6, tolerance=0.0)
    assert d.deform_report["stages"] == 1
    default, d = run()
    assert d.deform_report["stages"] == 2
    assert np.array_equal(default, staged)
    single, d = run(stage_angle=0)
    assert d.deform_report["stages"] == 1
    assert np.max(np.abs(staged - single)) > 0
    expect_value_error("stage_angle", lambda: ssmd.Deformation(V, F, fixed=fixed, handles=handles,
                                                               stage_angle=-1))


def test_volume_preservation():
    """A sphere squeezed between two caps keeps its volume with volume_preservation=True."""
    V, F = icosphere(3)
    fixed = np.flatnonzero(V[:, 2] < -0.8)
    handles = np.flatnonzero(V[:, 2] > 0.8)

    def volume(W):
        a, b, c = W[F[:, 0]], W[F[:, 1]], W[F[:, 2]]
        return np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6

    def run(**settings):
        d = ssmd.Deformation(V, F, fixed=fixed, handles=handles, m=30, **settings)
        d.translate([0.0, 0.0, -0.4])
        W = d.deform()
        assert d.deform_report["volume_preserved"] == settings.get("volume_preservation", False)
        return W

    free, kept = run(), run(volume_preservation=True)
    assert volume(free) < 0.97 * volume(V)
    assert abs(volume(kept) / volume(V) - 1) < 1e-9
    assert np.array_equal(kept[fixed], V[fixed])


def test_arap_energy(tube_mesh):
    """The ARAP energy: one patch per vertex is its full iteration, and it differs from the default."""
    V, F, fixed, handles = tube_mesh
    targets = bent_targets(V, handles)

    def run(energy, patches=None):
        d = ssmd.Deformation(V, F, fixed=fixed, handles=handles, m=30, energy=energy,
                             rotation_patches=patches)
        d.set_targets(targets)
        W = d.deform(iterations=6, tolerance=0.0)
        assert np.max(np.abs(W[handles] - targets)) <= 1e-9
        return W

    arap = run("arap")
    diagonal = np.linalg.norm(V.max(axis=0) - V.min(axis=0))
    assert np.max(np.abs(run("arap", 10**9) - arap)) <= 1e-9 * diagonal
    dual = run("dual_laplacian")
    assert np.max(np.linalg.norm(dual - arap, axis=1)) > 1e-4 * diagonal
    both = run("dual_laplacian_and_arap")
    assert np.max(np.linalg.norm(both - arap, axis=1)) > 1e-4 * diagonal
    assert np.max(np.linalg.norm(both - dual, axis=1)) > 1e-4 * diagonal
    expect_value_error("energy", lambda: ssmd.Deformation(V, F, fixed=fixed, handles=handles, energy="elastic"))


def test_exact_handles_and_fixed_vertices(tube_mesh):
    V, F, fixed, handles = tube_mesh
    V_before, F_before = V.copy(), F.copy()
    d = ssmd.Deformation(V, F, fixed=fixed, handles=handles, m=30)
    targets = bent_targets(V, handles)
    d.set_targets(targets)
    W = d.deform()
    assert np.max(np.abs(W[handles] - targets)) < 1e-9
    assert np.array_equal(W[fixed], V[fixed])
    assert np.max(np.abs(W - V)) > 0.5          # the tube did bend
    assert np.array_equal(d.vertices, W)
    assert np.array_equal(V, V_before) and np.array_equal(F, F_before)   # inputs untouched
    report = d.deform_report
    assert report["success"] and report["iterations"] >= 1 and report["max_control_residual"] < 1e-9
    assert d.preprocess_report["number_of_frequencies"] == 30


def test_roi_and_fixed_are_complements(tube_mesh):
    V, F, fixed, handles = tube_mesh
    d = ssmd.Deformation(V, F, fixed=fixed, handles=handles, m=20)
    assert np.array_equal(d.roi, np.setdiff1d(np.arange(len(V)), fixed))
    assert np.array_equal(d.handles, handles)


def test_rigid_motion_of_all_handles_is_reproduced(tube_mesh):
    """A free tube moved rigidly by its two end rings moves rigidly: at once
    for a translation; for a rotation, at the convergence of the iteration,
    which starts from the Laplacian coordinates of the rest shape."""
    V, F, _, _ = tube_mesh
    handles = np.concatenate([np.arange(20), np.arange(len(V) - 20, len(V))])
    t = np.array([0.3, -0.2, 0.5])
    d = ssmd.Deformation(V, F, handles=handles, m=40)
    d.set_targets(V[handles] + t)
    assert np.max(np.abs(d.deform(iterations=1) - (V + t))) < 1e-10
    a = np.radians(30)
    R = np.array([[np.cos(a), -np.sin(a), 0], [np.sin(a), np.cos(a), 0], [0, 0, 1]])
    d = ssmd.Deformation(V, F, handles=handles, m=40)
    d.set_targets(V[handles] @ R.T + t)
    errors = [np.max(np.abs(d.deform(iterations=k, tolerance=0.0) - (V @ R.T + t))) for k in (5, 25, 70)]
    assert errors[0] > errors[1] > errors[2] and errors[2] < 1e-5


def test_translate_and_rotate_move_targets(tube_mesh):
    V, F, fixed, handles = tube_mesh
    d = ssmd.Deformation(V, F, fixed=fixed, handles=handles, m=20)
    d.translate([0.0, 0.0, 1.0])
    assert np.allclose(d.targets, V[handles] + [0, 0, 1], atol=1e-15)
    d.translate([1.0, 0.0, 0.0], which=[0])
    assert np.allclose(d.targets[0], V[handles[0]] + [1, 0, 1], atol=1e-15)
    assert np.allclose(d.targets[1:], V[handles[1:]] + [0, 0, 1], atol=1e-15)
    d.reset()
    assert np.array_equal(d.targets, V[handles])
    a = np.radians(50)
    R = np.array([[1, 0, 0], [0, np.cos(a), -np.sin(a)], [0, np.sin(a), np.cos(a)]])
    d.rotate(R, center=[0, 0, 3])
    by_matrix = d.targets
    d.reset()
    d.rotate([np.cos(a / 2), np.sin(a / 2), 0, 0], center=[0, 0, 3])
    assert np.allclose(d.targets, by_matrix, atol=1e-14)
    assert np.allclose(by_matrix, (V[handles] - [0, 0, 3]) @ R.T + [0, 0, 3], atol=1e-14)


def test_reset_restores_the_input(tube_mesh):
    V, F, fixed, handles = tube_mesh
    d = ssmd.Deformation(V, F, fixed=fixed, handles=handles, m=20)
    d.translate([0.0, 0.5, 0.0])
    assert not np.array_equal(d.deform(), V)
    d.reset()
    assert np.array_equal(d.vertices, V)


def test_integer_types_of_faces_agree(tube_mesh):
    V, F, fixed, handles = tube_mesh
    results = []
    for faces in (F, F.astype(np.int32), F.astype(np.uint32), F.tolist()):
        d = ssmd.Deformation(V, faces, fixed=fixed, handles=handles.astype(np.int32), m=20)
        d.translate([0.0, 0.4, 0.0])
        results.append(d.deform())
    for W in results[1:]:
        assert np.array_equal(W, results[0])


def test_spectrum_of_the_sphere():
    """The Laplace-Beltrami eigenvalues of the unit sphere are l(l+1) with
    multiplicity 2l+1; the basis is orthonormal for the mass matrix."""
    V, F = icosphere(3)
    eigenvalues, basis, mass = ssmd.manifold_harmonics(V, F, 16, mass=True)
    assert eigenvalues.shape == (16,) and basis.shape == (len(V), 16) and mass.shape == (len(V),)
    expected = np.array([0] + [2] * 3 + [6] * 5 + [12] * 7, dtype=float)
    assert abs(eigenvalues[0]) < 1e-8
    assert np.allclose(eigenvalues[1:], expected[1:], rtol=0.03)
    assert np.allclose(basis.T @ (mass[:, None] * basis), np.eye(16), atol=1e-8)
    assert np.isclose(mass.sum(), 4 * np.pi, rtol=0.01)
    only_two = ssmd.manifold_harmonics(V, F, 16)
    assert len(only_two) == 2 and np.array_equal(only_two[0], eigenvalues)


def expect_value_error(match, call):
    with pytest.raises(ValueError, match=match):
        call()


def test_bad_input_raises_value_error(tube_mesh):
    V, F, fixed, handles = tube_mesh
    make = lambda **kw: ssmd.Deformation(kw.pop("V", V), kw.pop("F", F), **{"handles": handles, "fixed": fixed, "m": 20, **kw})
    expect_value_error(r"V must have shape \(k, 3\)", lambda: make(V=V[:, :2]))
    bad = V.copy(); bad[7, 1] = np.nan
    expect_value_error("V has a non-finite coordinate in row 7", lambda: make(V=bad))
    expect_value_error("F must hold integers", lambda: make(F=F.astype(float)))
    bad = F.copy(); bad[3, 2] = len(V)
    expect_value_error(r"F\[3\] refers to vertex", lambda: make(F=bad))
    bad = F.copy(); bad[5, 1] = bad[5, 0]
    expect_value_error(r"F\[5\] repeats a vertex", lambda: make(F=bad))
    expect_value_error("non-manifold", lambda: make(F=np.vstack([F, F[:1]])))
    expect_value_error("handles lists vertex", lambda: make(handles=np.concatenate([handles, handles[:1]])))
    expect_value_error("not in the region of interest", lambda: make(handles=fixed[:3]))
    expect_value_error("both in roi and in fixed", lambda: make(roi=np.arange(len(V))))
    expect_value_error("must be positive", lambda: make(m=0))
    expect_value_error("policy must be", lambda: make(policy="hard"))
    expect_value_error("algorithm must be", lambda: make(algorithm="arap"))
    expect_value_error("constraint_weight", lambda: make(constraint_weight=-1.0))
    expect_value_error("basis_cache: the 'spatial' algorithm", lambda: make(algorithm="spatial", basis_cache="x"))
    expect_value_error("not a vertex index", lambda: make(handles=[-1]))
    # Rejected by the library itself, with its message.
    with pytest.raises(ValueError, match="constraint"):
        make(handles=[], fixed=None)
    degenerate = V.copy(); degenerate[F[0, 2]] = 0.5 * (degenerate[F[0, 0]] + degenerate[F[0, 1]])
    with pytest.raises(ValueError, match="degenerate"):
        make(V=degenerate)
    isolated = np.vstack([V, [[5.0, 5.0, 5.0]]])
    expect_value_error("vertex 480 belongs to no face", lambda: make(V=isolated))
    with pytest.raises(ValueError, match="m = 700 frequencies"):
        ssmd.manifold_harmonics(V, F, 700)


def test_bad_targets_change_nothing(tube_mesh):
    V, F, fixed, handles = tube_mesh
    d = ssmd.Deformation(V, F, fixed=fixed, handles=handles, m=20)
    before = d.targets
    P = before + 1.0
    P[4, 2] = np.inf
    expect_value_error("non-finite coordinate in row 4", lambda: d.set_targets(P))
    expect_value_error("rows for", lambda: d.set_targets(P[:3]))
    expect_value_error("must be finite", lambda: d.translate([0, np.nan, 0]))
    expect_value_error("not a rotation", lambda: d.rotate(2 * np.eye(3)))
    expect_value_error("norm 1", lambda: d.rotate([2, 0, 0, 0]))
    expect_value_error("indices into handles", lambda: d.translate([0, 0, 1], which=[len(handles)]))
    expect_value_error("tolerance", lambda: d.deform(tolerance=float("nan")))
    assert np.array_equal(d.targets, before)
    assert np.array_equal(d.vertices, V)


def test_basis_cache(tube_mesh, tmp_path):
    V, F, fixed, handles = tube_mesh
    cache = tmp_path / "tube.basis"
    first = ssmd.Deformation(V, F, fixed=fixed, handles=handles, m=25, basis_cache=cache)
    assert first.preprocess_report["basis_computed"] and cache.exists()
    second = ssmd.Deformation(V, F, fixed=fixed, handles=handles, m=25, basis_cache=str(cache))
    assert not second.preprocess_report["basis_computed"]
    for d in (first, second):
        d.translate([0.0, 0.6, 0.0])
    assert np.array_equal(first.deform(), second.deform())
    with pytest.warns(UserWarning, match="holds 25 frequencies, not 30"):
        other = ssmd.Deformation(V, F, fixed=fixed, handles=handles, m=30, basis_cache=cache)
    assert other.preprocess_report["number_of_frequencies"] == 30
    cache.write_bytes(b"not a basis")
    with pytest.warns(UserWarning, match="cannot be used"):
        again = ssmd.Deformation(V, F, fixed=fixed, handles=handles, m=25, basis_cache=cache)
    assert again.preprocess_report["basis_computed"]
    saved = tmp_path / "saved.basis"
    again.save_basis(saved)
    moved = V.copy(); moved[:, 0] *= 1.5
    with pytest.raises(ValueError):
        ssmd.Deformation(moved, F, fixed=fixed, handles=handles, m=25).load_basis(saved)
    with pytest.raises(OSError):
        first.load_basis(tmp_path / "missing.basis")


def test_progress_callback_and_tqdm_like_bar(tube_mesh):
    V, F, fixed, handles = tube_mesh
    states = []
    ssmd.Deformation(V, F, fixed=fixed, handles=handles, m=30, progress=states.append)
    stages = [s["stage"] for s in states]
    assert stages[-1] == "finished" and len(stages) >= 2
    assert all(s["number_of_eigenpairs"] == 30 for s in states)

    class Bar:
        total, n, refreshed = None, 0, 0

        def refresh(self):
            self.refreshed += 1

    bar = Bar()
    ssmd.manifold_harmonics(V, F, 30, progress=ssmd.progress_bar(bar))
    assert bar.total == 30 and bar.n == 30 and bar.refreshed >= 2

    def failing(state):
        raise KeyError("stop")

    with pytest.raises(KeyError, match="stop"):
        ssmd.manifold_harmonics(V, F, 30, progress=failing)
    with pytest.raises(ValueError, match="callable"):
        ssmd.Deformation(V, F, fixed=fixed, handles=handles, progress=3)


def test_approximate_and_exact_basis():
    # 10,242 vertices against 8 per function of the approximate basis's
    # space (600 functions for m = 10): approximated by default.
    V, F = icosphere(5)
    handles = np.flatnonzero(V[:, 2] > 0.8)
    fixed = np.flatnonzero(V[:, 2] < -0.8)
    targets = V[handles] + np.array([0.3, 0.0, 0.2])
    results = {}
    for basis in ("approximate", "exact"):
        states = []
        kwargs = {} if basis == "approximate" else {"basis": basis}
        d = ssmd.Deformation(V, F, fixed=fixed, handles=handles, m=10, progress=states.append, **kwargs)
        stages = {s["stage"] for s in states}
        assert ("approximation" in stages) == (basis == "approximate")
        d.set_targets(targets)
        results[basis] = d.deform()
        assert np.max(np.abs(results[basis][handles] - targets)) <= 1e-12
    difference = np.max(np.linalg.norm(results["approximate"] - results["exact"], axis=1))
    assert 0 < difference < 0.02 * np.ptp(V, axis=0).max()
    expect_value_error("basis must be 'approximate' or 'exact'",
                       lambda: ssmd.Deformation(V, F, fixed=fixed, handles=handles, basis="fast"))


def test_basis_kept_in_float():
    V, F = icosphere(4)
    handles = np.flatnonzero(V[:, 2] > 0.8)
    fixed = np.flatnonzero(V[:, 2] < -0.8)
    targets = V[handles] + np.array([0.3, 0.0, 0.2])
    results = []
    for threshold in (None, 0):
        d = ssmd.Deformation(V, F, fixed=fixed, handles=handles, m=20,
                             single_precision_basis_threshold=threshold)
        assert d.preprocess_report["single_precision_basis"] == (threshold == 0)
        d.set_targets(targets)
        results.append(d.deform())
    # 2,562 vertices: double by default; every basis in float from 0 on.
    difference = np.max(np.linalg.norm(results[0] - results[1], axis=1))
    assert 0 < difference < 1e-5 * np.ptp(V, axis=0).max()
    expect_value_error("single_precision_basis_threshold must be 0 or positive",
                       lambda: ssmd.Deformation(V, F, fixed=fixed, handles=handles,
                                                single_precision_basis_threshold=-1))


def test_gil_is_released_during_the_eigensolve():
    V, F = icosphere(5)   # 10,242 vertices
    counter = [0]
    done = threading.Event()

    def solve():
        ssmd.manifold_harmonics(V, F, 60)
        done.set()

    worker = threading.Thread(target=solve)
    worker.start()
    while not done.is_set():
        counter[0] += 1
    worker.join()
    # Holding the GIL, the solve would leave this thread only the few
    # switch intervals before it starts.
    assert counter[0] > 100000


def test_no_reference_or_memory_leak_over_1000_calls(tube_mesh):
    V, F, fixed, handles = tube_mesh
    d = ssmd.Deformation(V, F, fixed=fixed, handles=handles, m=20)
    gc.collect()
    refs = (sys.getrefcount(V), sys.getrefcount(F), sys.getrefcount(handles))

    def calls(count):
        for i in range(count):
            d.set_targets(V[handles] + [0.0, 0.001 * (i % 7), 0.0])
            d.deform(iterations=2)
            d.refine(1)
            d.deform_report, d.preprocess_report, d.refine_report, d.targets, d.vertices
            ssmd.Deformation(V, F, fixed=fixed, handles=handles, m=8, algorithm="spatial") if i % 50 == 0 else None
            try:
                d.set_targets(np.full((len(handles), 3), np.nan))
            except ValueError:
                pass

    calls(50)
    gc.collect()
    tracemalloc.start()
    before = tracemalloc.get_traced_memory()[0]
    calls(1000)
    gc.collect()
    after = tracemalloc.get_traced_memory()[0]
    tracemalloc.stop()
    assert (sys.getrefcount(V), sys.getrefcount(F), sys.getrefcount(handles)) == refs
    assert after - before < 64 * 1024


def test_version():
    assert ssmd.__version__.count(".") == 2


def arap_energy(rest, deformed, F):
    """The as-rigid-as-possible energy of the refinement report, evaluated
    here: the best rotation per vertex one-ring, the cotangent weights
    clamped at 0 (the tube's are all 0 or more), divided by the weighted sum
    of the squared rest edge lengths."""
    n = len(rest)
    heads, tails, weights = [], [], []
    for k in range(3):
        a, b, c = F[:, k], F[:, (k + 1) % 3], F[:, (k + 2) % 3]
        u, v = rest[a] - rest[c], rest[b] - rest[c]
        cotangent = np.einsum("ij,ij->i", u, v) / np.linalg.norm(np.cross(u, v), axis=1)
        heads += [a, b]
        tails += [b, a]
        weights += [cotangent / 2, cotangent / 2]
    keys, inverse = np.unique(np.concatenate(heads) * n + np.concatenate(tails), return_inverse=True)
    w = np.maximum(np.bincount(inverse, weights=np.concatenate(weights)), 0)
    i, j = keys // n, keys % n
    e, d = rest[i] - rest[j], deformed[i] - deformed[j]
    covariance = np.zeros((n, 3, 3))
    np.add.at(covariance, i, w[:, None, None] * e[:, :, None] * d[:, None, :])
    U, _, Vt = np.linalg.svd(covariance)
    U[np.linalg.det(Vt.transpose(0, 2, 1) @ U.transpose(0, 2, 1)) < 0, :, 2] *= -1
    R = Vt.transpose(0, 2, 1) @ U.transpose(0, 2, 1)
    residual = d - np.einsum("kab,kb->ka", R[i], e)
    return np.sum(w * np.einsum("ij,ij->i", residual, residual)) / np.sum(w * np.einsum("ij,ij->i", e, e))


def test_refine_lowers_the_arap_energy_of_the_deformed_tube(tube_mesh):
    """Every vertex in the region, both end rings handles: the energies of
    the report are those of the positions before and after, they never rise,
    and the handles stay on their targets."""
    V, F, _, _ = tube_mesh
    handles = np.concatenate([np.arange(20), np.arange(len(V) - 20, len(V))])
    targets = V[handles].copy()
    targets[20:] = bent_targets(V, handles[20:])
    d = ssmd.Deformation(V, F, handles=handles, m=30)
    d.set_targets(targets)
    W = d.deform(iterations=6, tolerance=0.0)
    assert d.refine(50, 0) is True
    R = d.vertices
    report = d.refine_report
    assert report["success"] and report["message"] == ""
    assert report["iterations"] == 50 and not report["volume_preserved"]
    energies, seconds = report["energies"], report["seconds_at_iteration"]
    assert isinstance(energies, list) and isinstance(seconds, list)
    assert len(energies) == len(seconds) == 51
    assert energies[0] == report["energy_before"] and energies[-1] == report["energy_after"]
    assert all(b <= a * (1 + 1e-12) for a, b in zip(energies, energies[1:]))
    assert all(b >= a for a, b in zip(seconds, seconds[1:]))
    assert report["energy_after"] < 0.9 * report["energy_before"]
    assert report["total_seconds"] >= seconds[-1] >= 0
    assert 0 <= report["factorization_seconds"] <= report["total_seconds"]
    assert report["energy_before"] == pytest.approx(arap_energy(V, W, F), rel=1e-9)
    assert report["energy_after"] == pytest.approx(arap_energy(V, R, F), rel=1e-9)
    assert np.max(np.abs(R[handles] - targets)) <= 1e-12
    assert np.max(np.linalg.norm(R - W, axis=1)) > 1e-3
    # The report is a copy: changing it changes nothing.
    report["energies"].clear()
    assert len(d.refine_report["energies"]) == 51
    # The positions refined are the start of the next refinement.
    assert d.refine(0, 0.0)
    assert d.refine_report["iterations"] == 0 and d.refine_report["energies"] == [report["energy_after"]]
    assert np.array_equal(d.vertices, R)


@pytest.mark.parametrize("algorithm,policy", [("spectral", "exact"), ("spectral", "soft"), ("spatial", "exact")])
def test_refine_after_each_algorithm(tube_mesh, algorithm, policy):
    """The handles land on their targets (with the soft policy too), the
    vertices outside the region stay, the energy falls; the next deform()
    goes on from its own iteration."""
    V, F, fixed, handles = tube_mesh
    targets = bent_targets(V, handles)

    def deformed():
        d = ssmd.Deformation(V, F, fixed=fixed, handles=handles, m=30, algorithm=algorithm, policy=policy)
        d.set_targets(targets)
        return d, d.deform(iterations=6, tolerance=0.0)

    d, W = deformed()
    assert d.refine(40, 1e-9)
    R = d.vertices
    report = d.refine_report
    assert 1 <= report["iterations"] <= 40 and len(report["energies"]) == report["iterations"] + 1
    assert report["energy_after"] < report["energy_before"]
    assert np.max(np.abs(R[handles] - targets)) <= 1e-12
    assert np.array_equal(R[fixed], V[fixed])
    # The spectral algorithm with the exact policy reuses the factorization
    # of its detail transfer; the others factor once per set of handles.
    assert d.refine(5, 0.0)
    if algorithm == "spatial" or policy == "soft":
        assert report["factorization_seconds"] > d.refine_report["factorization_seconds"]
    other, _ = deformed()
    assert np.array_equal(d.deform(iterations=2, tolerance=0.0), other.deform(iterations=2, tolerance=0.0))


def test_refine_keeps_the_volume_on_demand():
    V, F = icosphere(3)
    fixed = np.flatnonzero(V[:, 2] < -0.8)
    handles = np.flatnonzero(V[:, 2] > 0.8)

    def volume(W):
        a, b, c = W[F[:, 0]], W[F[:, 1]], W[F[:, 2]]
        return np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6

    d = ssmd.Deformation(V, F, fixed=fixed, handles=handles, m=30, volume_preservation=True)
    d.translate([0.0, 0.0, -0.4])
    d.deform()
    assert d.refine(30, 0.0)
    assert d.refine_report["volume_preserved"]
    assert abs(volume(d.vertices) / volume(V) - 1) < 1e-9


def test_failed_refine_returns_false_and_changes_nothing(tube_mesh):
    V, F, fixed, handles = tube_mesh
    d = ssmd.Deformation(V, F, fixed=fixed, handles=handles, m=20)
    d.set_targets(bent_targets(V, handles))
    W = d.deform(iterations=4)
    for tolerance in (-1.0, float("nan")):
        assert d.refine(10, tolerance) is False
        report = d.refine_report
        assert not report["success"] and "tolerance" in report["message"]
        assert report["iterations"] == 0 and report["energies"] == []
        assert np.array_equal(d.vertices, W)
    with pytest.raises(TypeError):
        d.refine(-1)
    assert np.array_equal(d.vertices, W)
