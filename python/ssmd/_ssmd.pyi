# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Type stubs of the compiled module ssmd._ssmd."""

import os
from typing import Any, Callable, Dict, Literal, Optional, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

__version__: str

ArrayLike = npt.ArrayLike
PathLike = Union[str, os.PathLike]
ProgressCallback = Callable[[Dict[str, Any]], None]


class SolverError(RuntimeError):
    """A factorization or an eigensolver failed or did not converge."""


class Deformation:
    """Deforms a triangle mesh given as NumPy arrays."""

    def __init__(
        self,
        V: ArrayLike,
        F: ArrayLike,
        *,
        handles: ArrayLike,
        roi: Optional[ArrayLike] = None,
        fixed: Optional[ArrayLike] = None,
        m: int = 100,
        policy: str = "exact",
        algorithm: str = "spectral",
        energy: str = "dual_laplacian_and_arap",
        constraint_weight: Optional[float] = None,
        single_precision_basis: bool = False,
        rotation_patches: Optional[int] = None,
        stage_angle: Optional[float] = None,
        volume_preservation: bool = False,
        basis: str = "approximate",
        basis_cache: Optional[PathLike] = None,
        progress: Optional[ProgressCallback] = None,
        single_precision_basis_threshold: Optional[int] = None,
    ) -> None: ...

    @property
    def number_of_vertices(self) -> int: ...
    @property
    def handles(self) -> npt.NDArray[np.int64]: ...
    @property
    def roi(self) -> npt.NDArray[np.int64]: ...
    @property
    def vertices(self) -> npt.NDArray[np.float64]: ...
    @property
    def targets(self) -> npt.NDArray[np.float64]: ...
    @property
    def preprocess_report(self) -> Dict[str, Any]: ...
    @property
    def deform_report(self) -> Dict[str, Any]: ...

    def set_targets(self, P: ArrayLike, which: Optional[ArrayLike] = None) -> None: ...
    def translate(self, vector: ArrayLike, which: Optional[ArrayLike] = None) -> None: ...
    def rotate(
        self,
        rotation: ArrayLike,
        center: Optional[ArrayLike] = None,
        which: Optional[ArrayLike] = None,
    ) -> None: ...
    def deform(self, iterations: int = 10, tolerance: float = 1e-4) -> npt.NDArray[np.float64]: ...
    def reset(self) -> None: ...
    def save_basis(self, file: PathLike) -> None: ...
    def load_basis(self, file: PathLike, progress: Optional[ProgressCallback] = None) -> None: ...


@overload
def manifold_harmonics(
    V: ArrayLike, F: ArrayLike, m: int, *, progress: Optional[ProgressCallback] = None,
    mass: Literal[False] = False,
) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]: ...
@overload
def manifold_harmonics(
    V: ArrayLike, F: ArrayLike, m: int, *, progress: Optional[ProgressCallback] = None,
    mass: Literal[True],
) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64], npt.NDArray[np.float64]]: ...
