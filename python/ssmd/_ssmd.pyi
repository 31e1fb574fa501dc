# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Type stubs of the compiled module ssmd._ssmd.

Checked against the module by `python3 -m mypy.stubtest ssmd` and by the
test of python/tests/test_typing.py, which compares these signatures with
the module's own.
"""

import os
from typing import Any, Callable, Dict, Literal, Optional, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

__version__: str

_ArrayLike = npt.ArrayLike
_PathLike = Union[str, "os.PathLike[str]"]
_ProgressCallback = Callable[[Dict[str, Any]], None]
_Policy = Literal["exact", "soft"]
_Algorithm = Literal["spectral", "linear", "spatial"]
_Energy = Literal["dual_laplacian_and_arap", "dual_laplacian", "arap"]
_Basis = Literal["approximate", "exact"]
_FloatArray = npt.NDArray[np.float64]
_IndexArray = npt.NDArray[np.int64]


class SolverError(RuntimeError):
    """A factorization or an eigensolver failed or did not converge."""


class Deformation:
    """Deforms a triangle mesh (CGAL::Spectral_surface_mesh_deformation)."""

    def __init__(
        self,
        V: Any,
        F: Optional[_ArrayLike] = None,
        *,
        handles: _ArrayLike,
        roi: Optional[_ArrayLike] = None,
        fixed: Optional[_ArrayLike] = None,
        m: int = 100,
        policy: _Policy = "exact",
        algorithm: _Algorithm = "spectral",
        energy: _Energy = "dual_laplacian_and_arap",
        constraint_weight: Optional[float] = None,
        rotation_patches: Optional[int] = None,
        stage_angle: Optional[float] = None,
        volume_preservation: bool = False,
        basis: _Basis = "approximate",
        basis_cache: Optional[_PathLike] = None,
        progress: Optional[_ProgressCallback] = None,
        single_precision_basis_threshold: Optional[int] = None,
    ) -> None: ...

    @property
    def number_of_vertices(self) -> int: ...
    @property
    def handles(self) -> _IndexArray: ...
    @property
    def roi(self) -> _IndexArray: ...
    @property
    def vertices(self) -> _FloatArray: ...
    @property
    def targets(self) -> _FloatArray: ...
    @property
    def preprocess_report(self) -> Dict[str, Any]: ...
    @property
    def deform_report(self) -> Dict[str, Any]: ...
    @property
    def refine_report(self) -> Dict[str, Any]: ...

    def set_targets(self, P: _ArrayLike, which: Optional[_ArrayLike] = None) -> None: ...
    def translate(self, vector: _ArrayLike, which: Optional[_ArrayLike] = None) -> None: ...
    def rotate(
        self,
        rotation: _ArrayLike,
        center: Optional[_ArrayLike] = None,
        which: Optional[_ArrayLike] = None,
    ) -> None: ...
    def deform(self, iterations: int = 10, tolerance: float = 1e-4) -> _FloatArray: ...
    def refine(self, max_iterations: int = 100, tolerance: float = 1e-5) -> bool: ...
    def reset(self) -> None: ...
    def save_basis(self, file: _PathLike) -> None: ...
    def load_basis(self, file: _PathLike, progress: Optional[_ProgressCallback] = None) -> None: ...


# (V, F, m) arrays, or a mesh object and m by name: manifold_harmonics(mesh, m=30).
@overload
def manifold_harmonics(
    V: _ArrayLike, F: _ArrayLike, m: int, *,
    progress: Optional[_ProgressCallback] = None, mass: Literal[False] = False,
) -> Tuple[_FloatArray, _FloatArray]: ...
@overload
def manifold_harmonics(
    V: _ArrayLike, F: _ArrayLike, m: int, *,
    progress: Optional[_ProgressCallback] = None, mass: Literal[True],
) -> Tuple[_FloatArray, _FloatArray, _FloatArray]: ...
@overload
def manifold_harmonics(
    V: Any, F: None = None, *, m: int,
    progress: Optional[_ProgressCallback] = None, mass: Literal[False] = False,
) -> Tuple[_FloatArray, _FloatArray]: ...
@overload
def manifold_harmonics(
    V: Any, F: None = None, *, m: int,
    progress: Optional[_ProgressCallback] = None, mass: Literal[True],
) -> Tuple[_FloatArray, _FloatArray, _FloatArray]: ...

def from_file(file: _PathLike) -> Tuple[_FloatArray, _IndexArray]: ...
def to_file(file: _PathLike, V: Any, F: Optional[_ArrayLike] = None) -> None: ...
def read_selection(file: _PathLike, number_of_vertices: int) -> Tuple[_IndexArray, _IndexArray]: ...
def read_handle_transformation(file: _PathLike) -> _FloatArray: ...
