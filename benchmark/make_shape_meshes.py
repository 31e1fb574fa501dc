#!/usr/bin/env python3
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Writes the generated meshes of the quality cases that no sample mesh covers:
#   tube.off   a capped circular cylinder of radius 0.1 along z from 0 to 1
#              (cases/tube_twist.case): 96 vertices per ring, 340 rings,
#              caps triangulated by concentric rings; 33k vertices;
#   strip.off  an open flat strip [0, 4] x [0, 1] in the plane z = 0
#              (cases/strip_bend.case): 160 x 40 squares split along
#              alternating diagonals, 6.6k vertices.
#
# Usage: make_shape_meshes.py DIRECTORY

import math
import os
import sys


def write_off(path, points, faces):
    with open(path, "w") as out:
        out.write("OFF\n%d %d 0\n" % (len(points), len(faces)))
        for p in points:
            out.write("%.17g %.17g %.17g\n" % p)
        for f in faces:
            out.write("3 %d %d %d\n" % f)


def tube(radius=0.1, length=1.0, around=96, along=340, cap_rings=15):
    points, faces = [], []
    ring = []
    for k in range(along + 1):
        z = length * k / along
        ring.append(len(points))
        for i in range(around):
            a = 2 * math.pi * i / around
            points.append((radius * math.cos(a), radius * math.sin(a), z))

    def at(k, i):
        return ring[k] + i % around

    for k in range(along):
        for i in range(around):
            a, b, c, d = at(k, i), at(k, i + 1), at(k + 1, i + 1), at(k + 1, i)
            faces.append((a, b, c))
            faces.append((a, c, d))
    # Caps: concentric rings with the same number of vertices, then a centre.
    for z, outer, up in ((0.0, 0, False), (length, along, True)):
        previous = [at(outer, i) for i in range(around)]
        for r in range(cap_rings - 1, 0, -1):
            current = []
            for i in range(around):
                a = 2 * math.pi * (i + 0.5 * (cap_rings - r)) / around
                current.append(len(points))
                points.append((radius * r / cap_rings * math.cos(a), radius * r / cap_rings * math.sin(a), z))
            for i in range(around):
                p0, p1 = previous[i], previous[(i + 1) % around]
                q0, q1 = current[i], current[(i + 1) % around]
                for t in ((p0, q0, p1), (p1, q0, q1)):
                    faces.append((t[0], t[2], t[1]) if up else t)
            previous = current
        centre = len(points)
        points.append((0.0, 0.0, z))
        for i in range(around):
            t = (previous[i], centre, previous[(i + 1) % around])
            faces.append((t[0], t[2], t[1]) if up else t)
    return points, faces


def strip(length=4.0, width=1.0, cells_along=160, cells_across=40):
    points, faces = [], []
    for j in range(cells_across + 1):
        for i in range(cells_along + 1):
            points.append((length * i / cells_along, width * j / cells_across, 0.0))

    def at(i, j):
        return j * (cells_along + 1) + i

    for j in range(cells_across):
        for i in range(cells_along):
            a, b, c, d = at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)
            if (i + j) % 2 == 0:
                faces += [(a, b, c), (a, c, d)]
            else:
                faces += [(a, b, d), (b, c, d)]
    return points, faces


def main():
    directory = sys.argv[1]
    os.makedirs(directory, exist_ok=True)
    write_off(os.path.join(directory, "tube.off"), *tube())
    write_off(os.path.join(directory, "strip.off"), *strip())


if __name__ == "__main__":
    main()
