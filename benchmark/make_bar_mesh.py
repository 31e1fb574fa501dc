#!/usr/bin/env python3
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Writes the closed triangulated surface of a box bar, the mesh of the case
# quality/cases/bar_twist.case: a square cross-section of side 1 centred on
# the z axis, from z = 0 to z = 6, on a regular grid of 16 x 16 x 96 squares
# (6,658 vertices, 13,312 faces), every square split along the same diagonal,
# faces oriented outwards. Loop subdivision multiplies the vertex count by
# about 4 per level (26.6k, 106k, 426k, 1.7M).
#
# Usage: make_bar_mesh.py OUTPUT.off [--across N] [--along N]

import argparse


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("output")
    parser.add_argument("--across", type=int, default=16, help="squares across the bar")
    parser.add_argument("--along", type=int, default=96, help="squares along the bar")
    args = parser.parse_args()
    a, l = args.across, args.along
    side, length = 1.0, 6.0
    size = (a, a, l)
    step = (side / a, side / a, length / l)
    origin = (-side / 2, -side / 2, 0.0)

    index = {}
    points = []

    def vertex(i, j, k):
        key = (i, j, k)
        if key not in index:
            index[key] = len(points)
            points.append(tuple(origin[d] + key[d] * step[d] for d in range(3)))
        return index[key]

    faces = []
    # Each box face: the axis it is normal to, its side (0 or max), and the
    # two in-plane axes ordered so that (u, v, normal) is right-handed for the
    # max side; the min side swaps them to face outwards.
    for axis in range(3):
        u, v = [d for d in range(3) if d != axis]
        if (u, v, axis) not in ((0, 1, 2), (1, 2, 0), (2, 0, 1)):
            u, v = v, u
        for side_value, flip in ((size[axis], False), (0, True)):
            for s in range(size[u]):
                for t in range(size[v]):
                    corners = []
                    for du, dv in ((0, 0), (1, 0), (1, 1), (0, 1)):
                        key = [0, 0, 0]
                        key[axis] = side_value
                        key[u] = s + du
                        key[v] = t + dv
                        corners.append(vertex(*key))
                    q = corners[::-1] if flip else corners
                    faces.append((q[0], q[1], q[2]))
                    faces.append((q[0], q[2], q[3]))

    with open(args.output, "w") as out:
        out.write("OFF\n%d %d 0\n" % (len(points), len(faces)))
        for p in points:
            out.write("%.17g %.17g %.17g\n" % p)
        for f in faces:
            out.write("3 %d %d %d\n" % f)


if __name__ == "__main__":
    main()
