#!/usr/bin/env python3
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Measures how many drags a second ssmd_viewer answers without a browser:
the server's share of the update rate. Selects the upper part of the mesh
(above the given height quantile, the top 3 % as handle), then sends drags
along a circle, each one when the previous reply has arrived.

    drag_rate.py SSMD_VIEWER MESH [SECONDS [QUANTILE [SERVER_OPTIONS...]]]
"""

import json
import math
import os
import re
import struct
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_protocol import WebSocket  # noqa: E402


def main():
    viewer, mesh = sys.argv[1], sys.argv[2]
    seconds = float(sys.argv[3]) if len(sys.argv) > 3 else 5
    quantile = float(sys.argv[4]) if len(sys.argv) > 4 else 0.6
    server = subprocess.Popen([viewer, mesh, "--port", "0"] + sys.argv[5:], stdout=subprocess.PIPE, text=True)
    try:
        port = int(re.search(r"http://127\.0\.0\.1:(\d+)/", server.stdout.readline()).group(1))
        ws = WebSocket(port)
        n = ws.json()["vertices"]
        rest = struct.unpack(f"<{3 * n}f", ws.receive()[1][:12 * n])
        heights = sorted(rest[1::3])
        low, high = heights[int(quantile * n)], heights[int(0.97 * n)]
        roi = [i for i in range(n) if rest[3 * i + 1] > low]
        handle = [i for i in roi if rest[3 * i + 1] > high]
        ws.send(json.dumps({"type": "select", "roi": roi, "handle": handle}))
        ready = ws.reply()
        size = heights[-1] - heights[0]
        drags, deform, start = 0, 0.0, time.perf_counter()
        while time.perf_counter() - start < seconds:
            angle = 3 * (time.perf_counter() - start)
            ws.send(json.dumps({"type": "drag", "translation": [0.1 * size * math.sin(angle), 0.1 * size * (1 - math.cos(angle)), 0]}))
            reply = ws.reply()
            ws.receive()
            drags += 1
            deform += reply["deform_seconds"]
        elapsed = time.perf_counter() - start
        print(f"{n} vertices, {len(ready['region'])} region vertices, preprocess {ready['preprocess_seconds']:.2f} s: "
              f"{drags / elapsed:.1f} drags per second, deform {1000 * deform / drags:.1f} ms on average")
    finally:
        server.kill()
        server.wait()


if __name__ == "__main__":
    main()
