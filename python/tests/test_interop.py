# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Tests of what the package takes from and gives to the rest of Python:
meshio and trimesh-style meshes, array-likes, the files of ssmd_deform
(from_file, to_file, .sel and .def), the tqdm progress bar, and that the
package under test is the installed one."""

import io
import os
import sys

import numpy as np
import pytest

import ssmd
from conftest import tube


def deform(*mesh, **kwargs):
    """A bend of the tube given as *mesh (V, F or a mesh object)."""
    V = tube()[0]
    fixed, handles = np.arange(20), np.arange(len(V) - 20, len(V))
    d = ssmd.Deformation(*mesh, fixed=fixed, handles=handles, m=20, **kwargs)
    d.translate([0.0, 0.6, 0.0])
    return d.deform(iterations=4, tolerance=0.0)


class TrimeshLike:
    """What ssmd reads of a trimesh.Trimesh."""

    def __init__(self, V, F):
        self.vertices, self.faces = V, F


class Open3dLike:
    def __init__(self, V, F):
        self.vertices, self.triangles = V, F


def test_installed_package_is_tested():
    environment = os.environ.get("SSMD_PYTHON_ENVIRONMENT")
    if not environment:
        pytest.skip("SSMD_PYTHON_ENVIRONMENT is not set (run through ctest)")
    here = os.path.realpath(ssmd.__file__)
    assert here.startswith(os.path.realpath(environment) + os.sep), here
    assert os.path.realpath(sys.prefix) == os.path.realpath(environment)


def test_mesh_objects_give_the_result_of_the_arrays():
    V, F = tube()
    expected = deform(V, F)
    assert np.array_equal(deform(TrimeshLike(V, F)), expected)
    assert np.array_equal(deform(Open3dLike(V, F)), expected)
    assert np.array_equal(deform((V, F)), expected)
    # int32 faces and int vertices, as other packages give them
    assert np.array_equal(deform(TrimeshLike(V, F.astype(np.int32))), expected)


def test_meshio_mesh_gives_the_result_of_the_arrays():
    meshio = pytest.importorskip("meshio")
    V, F = tube()
    expected = deform(V, F)
    mesh = meshio.Mesh(V, [("triangle", F)])
    assert np.array_equal(deform(mesh), expected)
    # the triangles in two blocks, and vertex cells, which are not faces
    split = meshio.Mesh(V, [("triangle", F[:100]), ("vertex", np.arange(5)[:, None]), ("triangle", F[100:])])
    assert np.array_equal(deform(split), expected)
    V2, F2 = ssmd.mesh_arrays(split)
    assert V2.dtype == np.float64 and F2.dtype == np.int64 and np.array_equal(F2, F)

    quads = meshio.Mesh(V, [("triangle", F), ("quad", np.array([[0, 1, 21, 20]]))])
    with pytest.raises(ValueError, match="quad cells"):
        ssmd.mesh_arrays(quads)
    with pytest.raises(ValueError, match="no triangle"):
        ssmd.mesh_arrays(meshio.Mesh(V, [("line", np.array([[0, 1]]))]))


def test_meshio_reads_what_to_file_writes(tmp_path):
    meshio = pytest.importorskip("meshio")
    V, F = tube()
    ssmd.to_file(tmp_path / "tube.obj", V, F)
    mesh = meshio.read(tmp_path / "tube.obj")
    assert np.array_equal(mesh.points, V)
    assert np.array_equal(deform(mesh), deform(V, F))


def test_array_likes_in_numpy_arrays_out():
    V, F = tube()
    expected = deform(V, F)
    W = deform(V.tolist(), [tuple(f) for f in F.tolist()])
    assert type(W) is np.ndarray and np.array_equal(W, expected)

    class ArrayInterface:
        def __init__(self, a):
            self.a = a

        def __array__(self, dtype=None):
            return self.a if dtype is None else self.a.astype(dtype)

    assert np.array_equal(deform(ArrayInterface(V), ArrayInterface(F)), expected)
    # a Fortran-ordered float32 array: the result of its float64 values
    V32 = np.asfortranarray(V.astype(np.float32))
    assert np.array_equal(deform(V32, F), deform(V32.astype(np.float64), F))

    eigenvalues, basis = ssmd.manifold_harmonics(TrimeshLike(V, F), m=10)
    expected_eigenvalues, expected_basis = ssmd.manifold_harmonics(V.tolist(), F.tolist(), 10)
    assert type(eigenvalues) is np.ndarray and type(basis) is np.ndarray
    assert np.array_equal(eigenvalues, expected_eigenvalues) and np.array_equal(basis, expected_basis)


def test_bad_mesh_objects_raise_value_error():
    V, F = tube()
    with pytest.raises(ValueError, match="meshio mesh, an object with vertices and faces"):
        ssmd.Deformation(object(), handles=[0])
    with pytest.raises(ValueError, match=r"\(n, 3\) real numbers"):
        ssmd.mesh_arrays(TrimeshLike(V[:, :2], F))
    with pytest.raises(ValueError, match=r"\(f, 3\) integers"):
        ssmd.mesh_arrays(TrimeshLike(V, F.astype(float)))
    with pytest.raises(ValueError, match=r"\(n, 3\) real numbers"):
        ssmd.mesh_arrays((V.astype(str), F))
    # the library's own checks, on what the conversion gave
    with pytest.raises(ValueError, match="refers to vertex"):
        ssmd.Deformation(TrimeshLike(V, F + 1), handles=[0])
    with pytest.raises(TypeError, match="m=30"):
        ssmd.manifold_harmonics(TrimeshLike(V, F), 30)
    with pytest.raises(TypeError, match="needs m"):
        ssmd.manifold_harmonics(V, F)


def cyclic(F):
    """The triangles, each turned to start at its smallest index (GOCAD's
    writer turns them), orientation kept."""
    turns = np.argmin(F, axis=1)
    return np.array([np.roll(f, -k) for f, k in zip(F, turns)])


@pytest.mark.parametrize("extension", [".off", ".obj", ".ply", ".ts", ".OFF"])
def test_to_file_from_file_round_trip(tmp_path, extension):
    V, F = tube()
    V = V + np.array([1e-13, 1.0 / 3.0, -2.0 / 7.0])   # digits that a short format would lose
    path = tmp_path / ("tube" + extension)
    ssmd.to_file(path, V, F)
    V2, F2 = ssmd.from_file(path)
    assert V2.dtype == np.float64 and F2.dtype == np.int64
    assert np.array_equal(V2, V) and np.array_equal(cyclic(F2), cyclic(F))
    assert os.listdir(tmp_path) == [path.name]   # no temporary file left
    ssmd.to_file(str(path), TrimeshLike(V2, F2))   # a str path and a mesh object
    assert np.array_equal(ssmd.from_file(str(path))[0], V)


def test_stl_round_trip_keeps_the_triangles(tmp_path):
    # STL repeats the vertices of each triangle, in 32-bit floats: the
    # reader merges them, in its own order.
    V, F = tube()
    ssmd.to_file(tmp_path / "tube.stl", V, F)
    V2, F2 = ssmd.from_file(tmp_path / "tube.stl")
    assert V2.shape == V.shape and F2.shape == F.shape

    def triangles(V, F):
        return sorted(tuple(np.round(V[f].ravel(), 5)) for f in F)

    assert triangles(V2, F2) == triangles(V.astype(np.float32).astype(np.float64), F)


def test_from_file_keeps_the_vertex_order_of_the_file(tmp_path):
    path = tmp_path / "two.off"
    path.write_text("OFF\n# a comment\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0.5\n3 0 1 2\n3 1 3 2\n")
    V, F = ssmd.from_file(path)
    assert np.array_equal(V, [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0.5]])
    assert np.array_equal(F, [[0, 1, 2], [1, 3, 2]])


def test_file_errors(tmp_path):
    V, F = tube()
    with pytest.raises(FileNotFoundError):
        ssmd.from_file(tmp_path / "missing.off")
    (tmp_path / "folder.off").mkdir()
    with pytest.raises(IsADirectoryError):
        ssmd.from_file(tmp_path / "folder.off")
    with pytest.raises(ValueError, match=r"\.off, \.obj, \.ply, \.stl or \.ts, not \.xyz"):
        ssmd.from_file(tmp_path / "mesh.xyz")
    (tmp_path / "truncated.off").write_text("OFF\n4 2 0\n0 0 0\n1 0 0\n")
    with pytest.raises(ValueError, match="cannot read a polygon mesh"):
        ssmd.from_file(tmp_path / "truncated.off")
    (tmp_path / "quad.off").write_text("OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n")
    with pytest.raises(ValueError, match="not a triangle mesh: 1 of its 1 faces"):
        ssmd.from_file(tmp_path / "quad.off")
    with pytest.raises(FileNotFoundError):
        ssmd.to_file(tmp_path / "no" / "folder.off", V, F)
    with pytest.raises(ValueError, match="no extension"):
        ssmd.to_file(tmp_path / "mesh", V, F)
    with pytest.raises(ValueError, match="repeats a vertex"):
        ssmd.to_file(tmp_path / "bad.off", V, np.array([[0, 0, 1]]))
    assert not (tmp_path / "bad.off").exists()


def test_selection_files(tmp_path):
    V, F = tube()
    n = len(V)
    status = np.ones(n, dtype=int)
    status[:20] = 0
    status[-20:] = 2
    (tmp_path / "tube.sel").write_text("# status per vertex\n" + "\n".join(map(str, status)) + "\n")
    (tmp_path / "tube.def").write_text("1 0 0 0\n0 1 0 0.6\n0 0 1 0\n0 0 0 1\n")
    roi, handles = ssmd.read_selection(tmp_path / "tube.sel", n)
    assert np.array_equal(roi, np.arange(20, n)) and np.array_equal(handles, np.arange(n - 20, n))
    T = ssmd.read_handle_transformation(tmp_path / "tube.def")
    assert T.shape == (4, 4) and T[1, 3] == 0.6

    d = ssmd.Deformation(V, F, roi=roi, handles=handles, m=20)
    d.set_targets(V[handles] @ T[:3, :3].T + T[:3, 3])
    assert np.array_equal(d.deform(iterations=4, tolerance=0.0), deform(V, F))

    with pytest.raises(ValueError):
        ssmd.read_selection(tmp_path / "tube.sel", n + 1)
    (tmp_path / "bad.def").write_text("1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 1 1\n")
    with pytest.raises(ValueError):
        ssmd.read_handle_transformation(tmp_path / "bad.def")
    with pytest.raises(FileNotFoundError):
        ssmd.read_selection(tmp_path / "missing.sel", n)


def test_progress_with_tqdm(tube_mesh):
    tqdm = pytest.importorskip("tqdm").tqdm
    V, F, fixed, handles = tube_mesh
    out = io.StringIO()
    with tqdm(file=out, desc="basis") as bar:
        ssmd.Deformation(V, F, fixed=fixed, handles=handles, m=30, progress=ssmd.progress_bar(bar))
        assert bar.n == bar.total == 30
    assert "basis" in out.getvalue() and "30/30" in out.getvalue()

    # a bar of its own, closed when the basis is there
    out = io.StringIO()
    ssmd.manifold_harmonics(V, F, 30, progress=ssmd.progress_bar(file=out, desc="harmonics"))
    text = out.getvalue()
    assert "harmonics" in text and "30/30" in text and text.endswith("\n")


def test_progress_bar_without_tqdm(monkeypatch):
    monkeypatch.setitem(sys.modules, "tqdm.auto", None)   # import tqdm.auto fails
    with pytest.raises(ImportError, match="python3-tqdm"):
        ssmd.progress_bar()
    calls = []

    class Bar:
        total, n = None, 0

        def refresh(self):
            calls.append(self.n)

    report = ssmd.progress_bar(Bar())   # a bar given needs no tqdm
    report({"stage": "finished", "number_of_eigenpairs": 5, "converged_eigenpairs": 5})
    assert calls == [5]
