# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Meshes of other Python packages as the (V, F) arrays of ssmd.

Nothing here imports those packages: a mesh is recognized by its attributes,
so that ssmd depends on none of them.
"""

from typing import Any, Tuple

import numpy as np
import numpy.typing as npt

# Cells of meshio that are not faces of a surface and are left out: a mesh
# read from a file often carries its vertices or edges as such cells.
_LOWER_DIMENSIONAL_CELLS = {"vertex", "line", "line3"}


def mesh_arrays(mesh: Any) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]:
    """The vertex positions and triangles of a mesh object.

    Parameters
    ----------
    mesh : meshio.Mesh, trimesh-style object or (V, F) pair
        A ``meshio.Mesh`` (``points`` and ``cells``: its ``"triangle"``
        cells are the faces; vertex and line cells are ignored), any object
        with ``vertices`` and ``faces`` (``trimesh.Trimesh``) or
        ``vertices`` and ``triangles`` (Open3D) arrays, or a pair
        ``(V, F)`` of array-likes.

    Returns
    -------
    V : numpy.ndarray
        float64 (n, 3), the positions, in the unit of the mesh (no copy when
        they already are a float64 array).
    F : numpy.ndarray
        int64 (f, 3), the vertex indices of the triangles.

    Raises
    ------
    ValueError
        When ``mesh`` is none of these, has cells that are not triangles
        (quads, polygons, volume cells: triangulate or extract the surface
        first), positions that are not (n, 3) real numbers, or faces that are
        not (f, 3) integers.
    """
    if isinstance(mesh, (tuple, list)) and len(mesh) == 2:
        V, F = mesh
    elif hasattr(mesh, "points") and hasattr(mesh, "cells"):
        V, F = mesh.points, _meshio_triangles(mesh)
    elif hasattr(mesh, "vertices") and (hasattr(mesh, "faces") or hasattr(mesh, "triangles")):
        V = mesh.vertices
        F = mesh.faces if hasattr(mesh, "faces") else mesh.triangles
    else:
        raise ValueError("cannot take the vertices and triangles of a %s: give a meshio mesh, an object "
                         "with vertices and faces arrays (trimesh), or V and F" % type(mesh).__name__)
    V = np.asarray(V)
    F = np.asarray(F)
    if V.dtype.kind not in "fiu" or V.ndim != 2 or V.shape[1] != 3:
        raise ValueError("the vertices of the mesh must be (n, 3) real numbers, not %s %s"
                         % (V.dtype, V.shape))
    if (F.dtype.kind not in "iu" and F.size) or F.ndim != 2 or F.shape[1] != 3:
        raise ValueError("the faces of the mesh must be (f, 3) integers, not %s %s" % (F.dtype, F.shape))
    return V.astype(np.float64, copy=False), F.astype(np.int64, copy=False)


def _meshio_triangles(mesh: Any) -> Any:
    blocks = [(block.type, np.asarray(block.data)) for block in mesh.cells]
    others = sorted({kind for kind, _ in blocks if kind != "triangle" and kind not in _LOWER_DIMENSIONAL_CELLS})
    if others:
        raise ValueError("the meshio mesh has %s cells: ssmd deforms triangle meshes (triangulate the "
                         "polygons, or take the surface of a volume mesh, first)" % ", ".join(others))
    triangles = [data for kind, data in blocks if kind == "triangle"]
    if not triangles:
        raise ValueError("the meshio mesh has no triangle cell")
    return np.concatenate(triangles) if len(triangles) > 1 else triangles[0]
