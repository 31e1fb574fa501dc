#!/usr/bin/python3
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Write a deformed triangle mesh as a legacy VTK file with the per-vertex
scalar 'edge_change': the largest relative length change |l' - l| / l of the
edges at the vertex, between the rest mesh and the deformed mesh (same
connectivity). render_meshes.py --scalars edge_change colours by it, which
shows stretched and crumpled regions at a glance.

usage: edge_change_vtk.py REST.off DEFORMED.off OUTPUT.vtk
"""
import sys

import numpy as np


def read_off(path):
    with open(path) as f:
        words = []
        for line in f:
            line = line.split("#", 1)[0].split()
            words.extend(line)
    if not words or words[0] != "OFF":
        sys.exit("%s: not an OFF file" % path)
    n, m = int(words[1]), int(words[2])
    values = words[4:]
    points = np.array(values[:3 * n], dtype=float).reshape(n, 3)
    faces = []
    position = 3 * n
    for _ in range(m):
        k = int(values[position])
        if k != 3:
            sys.exit("%s: a face is not a triangle" % path)
        faces.append([int(v) for v in values[position + 1:position + 4]])
        position += 1 + k
    return points, np.array(faces, dtype=np.int64)


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    rest, faces = read_off(sys.argv[1])
    deformed, deformed_faces = read_off(sys.argv[2])
    if rest.shape != deformed.shape or not np.array_equal(faces, deformed_faces):
        sys.exit("the two meshes do not have the same connectivity")
    edges = np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]])
    before = np.linalg.norm(rest[edges[:, 0]] - rest[edges[:, 1]], axis=1)
    after = np.linalg.norm(deformed[edges[:, 0]] - deformed[edges[:, 1]], axis=1)
    change = np.abs(after - before) / np.maximum(before, 1e-300)
    per_vertex = np.zeros(len(rest))
    np.maximum.at(per_vertex, edges[:, 0], change)
    np.maximum.at(per_vertex, edges[:, 1], change)
    with open(sys.argv[3], "w") as out:
        out.write("# vtk DataFile Version 3.0\nedge change\nASCII\nDATASET POLYDATA\n")
        out.write("POINTS %d double\n" % len(deformed))
        np.savetxt(out, deformed, fmt="%.9g")
        out.write("POLYGONS %d %d\n" % (len(faces), 4 * len(faces)))
        np.savetxt(out, np.hstack([np.full((len(faces), 1), 3), faces]), fmt="%d")
        out.write("POINT_DATA %d\nSCALARS edge_change double 1\nLOOKUP_TABLE default\n" % len(rest))
        np.savetxt(out, per_vertex, fmt="%.6g")
    print("wrote %s (largest edge change %.1f %%)" % (sys.argv[3], 100 * per_vertex.max()))


if __name__ == "__main__":
    main()
