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

from ._ssmd import Deformation, SolverError, manifold_harmonics, __version__

__all__ = ["Deformation", "SolverError", "manifold_harmonics", "progress_bar", "__version__"]


def progress_bar(bar):
    """Returns a progress callback that drives a tqdm-like ``bar``.

    ``bar`` needs ``total``, ``n`` and ``refresh()`` (``tqdm.tqdm`` has them).
    It counts converged eigenpairs out of ``m``::

        from tqdm import tqdm
        with tqdm(desc="basis") as bar:
            d = ssmd.Deformation(V, F, handles=h, progress=ssmd.progress_bar(bar))
    """
    def report(state):
        bar.total = state["number_of_eigenpairs"]
        if state["stage"] == "finished":
            bar.n = bar.total
        else:
            bar.n = min(state["converged_eigenpairs"], bar.total)
        bar.refresh()
    return report
