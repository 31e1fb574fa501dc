# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The complete example of doc/python.md runs as written, on CGAL's
elephant (extracted by scripts/fetch_sample_meshes.sh)."""

import os
import re
import subprocess
import sys

import numpy as np
import pytest

import ssmd

DOC = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "doc", "python.md")


def documented_example():
    text = open(DOC, encoding="utf-8").read()
    match = re.search(r"<!-- the example that python/tests/test_documentation.py runs -->\n```python\n(.*?)```",
                      text, re.S)
    assert match, "the marked example is missing from doc/python.md"
    return match.group(1)


def test_the_documented_example_runs(tmp_path):
    meshes = os.environ.get("SSMD_SAMPLE_MESH_DIR", "")
    if not os.path.isfile(os.path.join(meshes, "elephant.off")):
        pytest.skip("no sample meshes (SSMD_SAMPLE_MESH_DIR, scripts/fetch_sample_meshes.sh)")
    pytest.importorskip("tqdm")
    code = documented_example()
    assert '"build/data/meshes/elephant.off"' in code
    code = code.replace('"build/data/meshes/elephant.off"', repr(os.path.join(meshes, "elephant.off")))
    run = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert re.search(r"basis in [0-9.]+ s, trunk moved by up to 0\.3[0-9]", run.stdout), run.stdout
    assert "100/100" in run.stderr   # the progress bar, full
    V, F = ssmd.from_file(os.path.join(meshes, "elephant.off"))
    W, F2 = ssmd.from_file(tmp_path / "elephant_trunk.off")
    assert np.array_equal(F2, F) and W.shape == V.shape
    feet = V[:, 1] < -0.3
    assert np.array_equal(W[feet], V[feet]) and np.abs(W - V).max() > 0.2
