#!/usr/bin/python3
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Write a deformation selection (.sel) and a handle transformation (.def), the
format of the Botsch & Sorkine 2008 benchmark, for an OFF mesh from boxes:

  make_selection.py mesh.off out_prefix --handle xmin ymin zmin xmax ymax zmax
      --fixed xmin ymin zmin xmax ymax zmax [--fixed ...]
      --rotate ax ay az degrees cx cy cz [--translate tx ty tz]

Vertices inside a --fixed box are outside the region of interest (status 0),
vertices inside the --handle box are control vertices (status 2), all others
are in the region of interest (status 1). The handle moves by the rotation
about the axis (ax, ay, az) through (cx, cy, cz), then the translation.
"""
import argparse
import math


def read_off_points(path):
    words = []
    with open(path) as f:
        for line in f:
            words.extend(line.split("#", 1)[0].split())
            if len(words) > 4 and len(words) >= 4 + 3 * int(words[1]):
                break
    if not words or not words[0].endswith("OFF"):
        raise SystemExit("%s is not an OFF file" % path)
    n = int(words[1])
    return [tuple(map(float, words[4 + 3 * i:7 + 3 * i])) for i in range(n)]


def inside(p, box):
    return all(box[k] <= p[k] <= box[k + 3] for k in range(3))


def rotation_matrix(axis, degrees):
    x, y, z = axis
    length = math.sqrt(x * x + y * y + z * z)
    x, y, z = x / length, y / length, z / length
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    t = 1 - c
    return [[t * x * x + c, t * x * y - s * z, t * x * z + s * y],
            [t * x * y + s * z, t * y * y + c, t * y * z - s * x],
            [t * x * z - s * y, t * y * z + s * x, t * z * z + c]]


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("mesh")
    parser.add_argument("prefix")
    parser.add_argument("--handle", nargs=6, type=float, required=True)
    parser.add_argument("--fixed", nargs=6, type=float, action="append", default=[])
    parser.add_argument("--rotate", nargs=7, type=float, default=[0, 0, 1, 0, 0, 0, 0])
    parser.add_argument("--translate", nargs=3, type=float, default=[0, 0, 0])
    args = parser.parse_args()

    points = read_off_points(args.mesh)
    status = []
    for p in points:
        if any(inside(p, box) for box in args.fixed):
            status.append(0)
        elif inside(p, args.handle):
            status.append(2)
        else:
            status.append(1)
    if 2 not in status:
        raise SystemExit("the handle box contains no vertex")
    with open(args.prefix + ".sel", "w") as f:
        f.write("# per vertex status: 0=fixed, 1=deformable-region, 2=handle\n")
        f.write("# %d vertices\n" % len(points))
        f.write("\n".join(str(s) for s in status) + "\n")

    R = rotation_matrix(args.rotate[0:3], args.rotate[3])
    c = args.rotate[4:7]
    t = [c[i] - sum(R[i][j] * c[j] for j in range(3)) + args.translate[i] for i in range(3)]
    with open(args.prefix + ".def", "w") as f:
        f.write("# 4x4 handle transformation matrix\n")
        for i in range(3):
            f.write(" ".join("%.9f" % v for v in R[i] + [t[i]]) + "\n")
        f.write("0 0 0 1\n")
    print("%s.sel: %d fixed, %d handle, %d region-of-interest vertices"
          % (args.prefix, status.count(0), status.count(2), status.count(1)))


if __name__ == "__main__":
    main()
