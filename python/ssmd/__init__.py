# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Spectral surface mesh deformation from NumPy.

Deforms triangle meshes with the spectral dual Laplacian editing of the C++
package (``CGAL::Spectral_surface_mesh_deformation``)::

    import ssmd
    d = ssmd.Deformation(V, F, handles=hand, fixed=feet)
    d.translate([0.0, 0.1, 0.0])
    W = d.deform()

See ``doc/python.md`` for the manual.
"""

from typing import Any, Callable, Dict

try:
    import numpy as _numpy  # noqa: F401  (the compiled module exchanges NumPy arrays)
except ImportError:  # pragma: no cover - depends on the interpreter
    # On Debian the package is built for /usr/bin/python3 and NumPy comes from
    # python3-numpy; another CPython of the same minor version (pyenv, for
    # instance) can load that NumPy too.
    import sys as _sys
    import sysconfig as _sysconfig

    _debian_numpy = "/usr/lib/python3/dist-packages"
    if (_sys.implementation.name == "cpython"
            and _sysconfig.get_config_var("EXT_SUFFIX") == ".cpython-%d%d-x86_64-linux-gnu.so" % _sys.version_info[:2]
            and __import__("os").path.isdir(_debian_numpy + "/numpy")):
        _sys.path.append(_debian_numpy)
        import numpy as _numpy  # noqa: F401
    else:
        raise ImportError("ssmd needs NumPy (Debian: apt-get install python3-numpy)") from None

from ._meshes import mesh_arrays
from ._ssmd import (Deformation, SolverError, __version__, from_file, manifold_harmonics,
                    read_handle_transformation, read_selection, to_file)

__all__ = ["Deformation", "SolverError", "from_file", "manifold_harmonics", "mesh_arrays", "progress_bar",
           "read_handle_transformation", "read_selection", "to_file", "__version__"]


def progress_bar(bar: Any = None, **tqdm_arguments: Any) -> Callable[[Dict[str, Any]], None]:
    """A progress callback that shows the computation of the basis on a bar.

    The bar counts converged eigenpairs out of ``m``::

        d = ssmd.Deformation(V, F, handles=h, progress=ssmd.progress_bar())

    Parameters
    ----------
    bar : tqdm-like, optional
        Anything with ``total``, ``n`` and ``refresh()`` (``tqdm.tqdm`` has
        them); it is left open. Default: a new ``tqdm.auto.tqdm`` bar (a
        widget in Jupyter, text in a terminal), closed when the basis is
        computed.
    **tqdm_arguments
        With no ``bar``: arguments of the new bar (``desc``, ``file``,
        ``leave``, ...).

    Returns
    -------
    callable
        The callback to give as ``progress``; it raises nothing.

    Raises
    ------
    ImportError
        With no ``bar``, when tqdm is not installed (Debian: python3-tqdm;
        pip: tqdm).
    """
    if bar is None:
        try:
            from tqdm.auto import tqdm
        except ImportError:
            raise ImportError("ssmd.progress_bar() draws its bar with tqdm, which is not installed "
                              "(Debian: apt-get install python3-tqdm; pip install tqdm)") from None
        tqdm_arguments.setdefault("desc", "basis")
        tqdm_arguments.setdefault("unit", " eigenpairs")
        bar = tqdm(**tqdm_arguments)
        owned = True
    else:
        owned = False

    def report(state: Dict[str, Any]) -> None:
        bar.total = state["number_of_eigenpairs"]
        if state["stage"] == "finished":
            bar.n = bar.total
        else:
            bar.n = min(state["converged_eigenpairs"], bar.total)
        bar.refresh()
        if owned and state["stage"] == "finished":
            bar.close()
    return report
