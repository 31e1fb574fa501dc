#!/usr/bin/python3
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Render meshes headless with f3d (under xvfb-run) and put the pictures side
by side, each with a caption, in one PNG.

usage: render_meshes.py OUTPUT.png [--size 360] [--azimuth DEG] [--elevation DEG]
                        [--up +Y] [--position X,Y,Z --focus X,Y,Z]
                        [--scalars NAME --range MIN,MAX]
                        CAPTION=MESH [CAPTION=MESH ...]

--position and --focus place the camera (a close-up of a detail); otherwise
f3d frames the whole mesh from the azimuth and elevation. --scalars colours
the meshes by a point array of theirs (e.g. the 'edge_change' of the VTK files
of edge_change_vtk.py), blue to red over --range, with a colour bar.
"""
import argparse
import os
import subprocess
import sys
import tempfile

from PIL import Image, ImageDraw, ImageFont


def render(mesh, png, size, azimuth, elevation, up, position=None, focus=None, scalars=None,
           value_range=None):
    command = ["xvfb-run", "-a", "f3d", mesh, "--output=" + png,
               "--resolution=%d,%d" % (size, size), "--up=" + up,
               "--camera-azimuth-angle=%g" % azimuth,
               "--camera-elevation-angle=%g" % elevation,
               "--color=0.85,0.8,0.7", "--fxaa", "--bg-color=1,1,1"]
    if position and focus:
        command += ["--camera-position=" + position, "--camera-focal-point=" + focus]
    if scalars:
        command += ["--scalars=" + scalars, "--comp=0", "--bar"]
        if value_range:
            command += ["--range=" + value_range]
    result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    if result.returncode != 0 or not os.path.exists(png):
        sys.exit("rendering %s failed:\n%s" % (mesh, result.stdout.decode(errors="replace")))


def caption_font():
    for path in ("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",):
        if os.path.exists(path):
            return ImageFont.truetype(path, 18)
    return ImageFont.load_default()


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("output")
    parser.add_argument("panels", nargs="+", metavar="CAPTION=MESH")
    parser.add_argument("--size", type=int, default=360)
    parser.add_argument("--azimuth", type=float, default=0.0)
    parser.add_argument("--elevation", type=float, default=0.0)
    parser.add_argument("--up", default="+Y")
    parser.add_argument("--position", help="camera position X,Y,Z (with --focus)")
    parser.add_argument("--focus", help="camera focal point X,Y,Z (with --position)")
    parser.add_argument("--scalars", help="colour by this point array")
    parser.add_argument("--range", help="MIN,MAX of the colour scale (with --scalars)")
    args = parser.parse_args()

    caption_height = 28
    pictures = []
    with tempfile.TemporaryDirectory() as workdir:
        for index, panel in enumerate(args.panels):
            caption, _, mesh = panel.rpartition("=")
            if not mesh:
                sys.exit("panels are given as CAPTION=MESH, got %r" % panel)
            png = os.path.join(workdir, "%d.png" % index)
            render(mesh, png, args.size, args.azimuth, args.elevation, args.up, args.position,
                   args.focus, args.scalars, args.range)
            pictures.append((caption, Image.open(png).convert("RGB")))

        sheet = Image.new("RGB", (args.size * len(pictures), args.size + caption_height), "white")
        draw = ImageDraw.Draw(sheet)
        font = caption_font()
        for index, (caption, picture) in enumerate(pictures):
            sheet.paste(picture, (index * args.size, 0))
            width = draw.textlength(caption, font=font)
            draw.text((index * args.size + (args.size - width) / 2, args.size + 8), caption,
                      fill="black", font=font)
        sheet.save(args.output)
    print("wrote", args.output)


if __name__ == "__main__":
    main()
