#!/usr/bin/env python3
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Protocol test of ssmd_viewer: starts the server on a mesh, sends malformed,
unknown, out-of-range, non-finite and oversized commands, checks that each
one is answered with an error and that the same connection then serves a
correct selection and drag (handle moved by the translation, fixed vertices
in place), a refinement in chunks (an energy that falls, the handle kept on
its targets, the cap of iterations, a drag that starts it again), a reset and
a save.

    check_protocol.py SSMD_VIEWER MESH

Debian's Python has no WebSocket client, hence the minimal one below
(RFC 6455: handshake, masked client frames, fragmented server messages).
"""

import base64
import json
import math
import os
import re
import socket
import struct
import subprocess
import sys
import time


class WebSocket:
    def __init__(self, port, origin=None):
        self.sock = socket.create_connection(("127.0.0.1", port), timeout=60)
        key = base64.b64encode(os.urandom(16)).decode()
        request = (f"GET /ws HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nUpgrade: websocket\r\n"
                   f"Connection: Upgrade\r\nSec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n")
        if origin:
            request += f"Origin: {origin}\r\n"
        self.sock.sendall((request + "\r\n").encode())
        response = b""
        while b"\r\n\r\n" not in response:
            chunk = self.sock.recv(4096)
            if not chunk:
                break
            response += chunk
        self.status = response.split(b"\r\n", 1)[0].decode()
        self.pending = response.split(b"\r\n\r\n", 1)[1] if b"\r\n\r\n" in response else b""

    def send(self, payload, opcode=1):
        if isinstance(payload, str):
            payload = payload.encode()
        mask = os.urandom(4)
        length = len(payload)
        if length < 126:
            header = struct.pack("!BB", 0x80 | opcode, 0x80 | length)
        elif length < 65536:
            header = struct.pack("!BBH", 0x80 | opcode, 0x80 | 126, length)
        else:
            header = struct.pack("!BBQ", 0x80 | opcode, 0x80 | 127, length)
        masked = bytes(b ^ mask[i % 4] for i, b in enumerate(payload)) if length < 65536 else \
            (int.from_bytes(payload, "big") ^ int.from_bytes((mask * (length // 4 + 1))[:length], "big")).to_bytes(length, "big")
        self.sock.sendall(header + mask + masked)

    def _read(self, n):
        while len(self.pending) < n:
            chunk = self.sock.recv(1 << 20)
            if not chunk:
                raise ConnectionError("the server closed the connection")
            self.pending += chunk
        data, self.pending = self.pending[:n], self.pending[n:]
        return data

    def receive(self):
        """Returns (opcode, payload) of the next data message, its fragments joined."""
        message_opcode, message = None, b""
        while True:
            b0, b1 = self._read(2)
            length = b1 & 0x7F
            if length == 126:
                (length,) = struct.unpack("!H", self._read(2))
            elif length == 127:
                (length,) = struct.unpack("!Q", self._read(8))
            payload = self._read(length)
            opcode = b0 & 0x0F
            if opcode == 8:
                raise ConnectionError("the server closed the WebSocket")
            if opcode in (0, 1, 2):
                message_opcode = message_opcode or opcode
                message += payload
                if b0 & 0x80:
                    return message_opcode, message

    def json(self):
        opcode, payload = self.receive()
        if opcode != 1:
            raise AssertionError(f"expected a JSON message, got {len(payload)} binary bytes")
        return json.loads(payload)

    def reply(self):
        """The next message that is not a progress report."""
        while True:
            message = self.json()
            if message["type"] != "progress":
                return message


failures = []


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what)
    if not condition:
        failures.append(what)


def expect_error(ws, payload, what, opcode=1):
    ws.send(payload, opcode)
    message = ws.reply()
    check(message["type"] == "error", f"{what}: answered with an error ({message.get('message', message['type'])})")


def main():
    viewer, mesh = sys.argv[1], sys.argv[2]
    server = subprocess.Popen([viewer, mesh, "--port", "0", "--frequencies", "30", "--max-message", str(1 << 20),
                               "--refine-iterations", "4", "--refine-max-iterations", "10"],
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        line = server.stdout.readline()
        match = re.search(r"http://127\.0\.0\.1:(\d+)/", line)
        if not match:
            print("FAIL the server did not start:", line, server.stderr.read())
            return 1
        port = int(match.group(1))

        other = WebSocket(port, origin="http://evil.example")
        check(" 403" in other.status, f"a WebSocket from another origin is refused ({other.status})")

        ws = WebSocket(port, origin=f"http://127.0.0.1:{port}")
        check(" 101" in ws.status, f"handshake ({ws.status})")
        header = ws.json()
        check(header["type"] == "mesh", "the mesh is announced")
        check(header.get("refine_iterations") == 4 and header.get("refine_max_iterations") == 10,
              "the mesh header gives the refinement's chunk and cap")
        n, f = header["vertices"], header["faces"]
        opcode, data = ws.receive()
        check(opcode == 2 and len(data) == 12 * n + 12 * f, "the mesh follows as Float32 positions + Uint32 faces")
        rest = struct.unpack(f"<{3 * n}f", data[:12 * n])

        expect_error(ws, "{not json", "malformed JSON")
        expect_error(ws, "[1, 2, 3]", "a JSON array")
        expect_error(ws, '{"type": "explode"}', "an unknown type")
        expect_error(ws, '{"type": 7}', "a type that is not a string")
        expect_error(ws, '{"type": "drag", "translation": [1, 0, 0]}', "a drag before a selection")
        expect_error(ws, '{"type": "refine"}', "a refinement before a selection")
        expect_error(ws, json.dumps({"type": "select", "roi": [0, 1], "handle": [n]}), "an index out of range")
        expect_error(ws, json.dumps({"type": "select", "roi": [-1], "handle": [0]}), "a negative index")
        expect_error(ws, json.dumps({"type": "select", "roi": [0.5], "handle": [0]}), "a fractional index")
        expect_error(ws, json.dumps({"type": "select", "roi": [0, 1], "handle": []}), "an empty handle")
        expect_error(ws, b"\x00\x01\x02", "a binary message", opcode=2)
        expect_error(ws, "x" * ((1 << 20) + 10), "an oversized message")

        # The region: the vertices above the 60th percentile of height, the
        # handle the top ones, the fixed ones the bottom ones of the region.
        heights = sorted(rest[3 * i + 1] for i in range(n))
        low, high = heights[int(0.6 * n)], heights[int(0.97 * n)]
        roi = [i for i in range(n) if rest[3 * i + 1] > low]
        handle = [i for i in roi if rest[3 * i + 1] > high]
        fixed = [i for i in roi if rest[3 * i + 1] < heights[int(0.63 * n)]]
        ws.send(json.dumps({"type": "select", "roi": roi, "fixed": fixed, "handle": handle}))
        progress = []
        ready = ws.json()
        while ready["type"] == "progress":
            progress.append(ready)
            ready = ws.json()
        check(len(progress) > 0 and progress[-1]["stage"] == "finished" and progress[-1]["fraction"] == 1,
              f"the basis reports its progress ({len(progress)} messages, the last one {progress[-1]['stage'] if progress else None})")
        check(ready["type"] == "ready", f"a valid selection is prepared ({ready.get('message', '')})")
        if ready["type"] != "ready":
            return 1
        region = ready["region"]

        expect_error(ws, '{"type": "drag", "translation": [NaN, 0, 0]}', "NaN (not JSON)")
        expect_error(ws, '{"type": "drag", "translation": [1e999, 0, 0]}', "an infinite translation")
        expect_error(ws, '{"type": "drag", "translation": [1, 0]}', "a translation of two numbers")
        expect_error(ws, '{"type": "drag", "translation": ["1", 0, 0]}', "a translation given as strings")
        expect_error(ws, '{"type": "drag", "rotation": [0, 0, 0, 0]}', "a zero quaternion")
        expect_error(ws, '{"type": "drag", "iterations": 0}', "zero iterations")
        expect_error(ws, '{"type": "drag", "iterations": 2.5}', "fractional iterations")

        radius = (max(rest[1::3]) - min(rest[1::3]))
        t = [0.05 * radius, 0.02 * radius, 0.0]
        ws.send(json.dumps({"type": "drag", "translation": t, "rotation": [1, 0, 0, 0], "iterations": 5}))
        reply = ws.reply()
        check(reply["type"] == "deformed" and reply["count"] == len(region) and reply["iterations"] >= 1,
              f"the drag is answered with the region ({reply.get('iterations')} solves)")
        opcode, data = ws.receive()
        check(opcode == 2 and len(data) == 12 * len(region), "its positions follow")
        positions = struct.unpack(f"<{3 * len(region)}f", data)
        where = {v: j for j, v in enumerate(region)}
        handle_error = max(abs(positions[3 * where[v] + k] - rest[3 * v + k] - t[k]) for v in handle for k in range(3))
        fixed_error = max(abs(positions[3 * where[v] + k] - rest[3 * v + k]) for v in fixed for k in range(3))
        check(handle_error < 1e-3 * radius, f"the handle moved by the translation (error {handle_error:.2e})")
        check(fixed_error < 1e-5 * radius, f"the fixed vertices stayed (error {fixed_error:.2e})")
        check(reply["deform_seconds"] > 0 and reply["server_seconds"] >= reply["deform_seconds"], "timings are reported")

        # A turn by 30 degrees about z around the centroid of the handle.
        angle = math.radians(30)
        c = ready["center"]
        ws.send(json.dumps({"type": "drag", "translation": t, "rotation": [math.cos(angle / 2), 0, 0, math.sin(angle / 2)]}))
        reply = ws.reply()
        opcode, data = ws.receive()
        positions = struct.unpack(f"<{3 * len(region)}f", data)
        turn_error = 0
        for v in handle:
            x, y, z = (rest[3 * v + k] - c[k] for k in range(3))
            target = (c[0] + math.cos(angle) * x - math.sin(angle) * y + t[0],
                      c[1] + math.sin(angle) * x + math.cos(angle) * y + t[1], c[2] + z + t[2])
            turn_error = max(turn_error, max(abs(positions[3 * where[v] + k] - target[k]) for k in range(3)))
        check(reply["type"] == "deformed" and turn_error < 1e-3 * radius,
              f"a turned handle lands on its targets (error {turn_error:.2e})")

        # The refinement of the turned shape, chunk after chunk.
        def turned_handle_error(positions):
            error = 0
            for v in handle:
                x, y, z = (rest[3 * v + k] - c[k] for k in range(3))
                target = (c[0] + math.cos(angle) * x - math.sin(angle) * y + t[0],
                          c[1] + math.sin(angle) * x + math.cos(angle) * y + t[1], c[2] + z + t[2])
                error = max(error, max(abs(positions[3 * where[v] + k] - target[k]) for k in range(3)))
            return error

        for payload, what in [('{"type": "refine", "iterations": 0}', "zero refinement iterations"),
                              ('{"type": "refine", "iterations": 101}', "too many refinement iterations"),
                              ('{"type": "refine", "iterations": 1.5}', "fractional refinement iterations"),
                              ('{"type": "refine", "tolerance": -1}', "a negative tolerance"),
                              ('{"type": "refine", "tolerance": "small"}', "a tolerance given as a string")]:
            expect_error(ws, payload, what)
        dragged = positions
        ws.send(json.dumps({"type": "refine", "iterations": 3, "tolerance": 0}))
        reply = ws.reply()
        check(reply["type"] == "refined" and reply["count"] == len(region) and reply["iterations"] == 3
              and reply["total_iterations"] == 3 and reply["max_iterations"] == 10 and not reply["done"],
              f"a refinement chunk is answered with the region ({reply.get('iterations')} iterations)")
        opcode, data = ws.receive()
        check(opcode == 2 and len(data) == 12 * len(region), "its positions follow")
        positions = struct.unpack(f"<{3 * len(region)}f", data)
        check(reply["energy_start"] == reply["energy_before"] and 0 < reply["energy_after"] < reply["energy_before"],
              f"the energy falls ({reply['energy_before']:.4e} -> {reply['energy_after']:.4e})")
        moved = max(abs(a - b) for a, b in zip(positions, dragged))
        handle_error = turned_handle_error(positions)
        fixed_error = max(abs(positions[3 * where[v] + k] - rest[3 * v + k]) for v in fixed for k in range(3))
        check(moved > 1e-5 * radius and handle_error < 1e-3 * radius and fixed_error < 1e-5 * radius,
              f"the region moved by up to {moved:.2e}, the handle stays on its targets (error {handle_error:.2e}), "
              f"the fixed vertices stay (error {fixed_error:.2e})")
        check(reply["refine_seconds"] > 0 and reply["server_seconds"] >= reply["refine_seconds"],
              "the refinement's timings are reported")
        chunks = [reply]
        while not chunks[-1]["done"] and len(chunks) < 50:
            ws.send('{"type": "refine"}')
            chunks.append(ws.reply())
            ws.receive()
        last = chunks[-1]
        check(all(r["type"] == "refined" for r in chunks) and last["done"]
              and (last["converged"] or last["total_iterations"] == 10) and last["total_iterations"] <= 10
              and all(r["iterations"] <= 4 for r in chunks[1:]),
              f"chunks of at most 4 iterations until done ({last['total_iterations']} iterations, "
              f"converged {last['converged']})")
        # An absolute slack: the comparisons hold whatever the sign.
        slack = 1e-9 * abs(reply["energy_start"])
        check(all(r["energy_start"] == reply["energy_start"] for r in chunks)
              and all(b["energy_after"] <= a["energy_after"] + slack for a, b in zip(chunks, chunks[1:]))
              and all(abs(b["energy_before"] - a["energy_after"]) <= slack for a, b in zip(chunks, chunks[1:])),
              f"each chunk goes on from the previous one, the energy never rises "
              f"({reply['energy_start']:.4e} -> {last['energy_after']:.4e})")
        if not last["converged"]:
            ws.send('{"type": "refine"}')
            reply = ws.reply()
            ws.receive()
            check(reply["type"] == "refined" and reply["iterations"] == 0 and reply["done"]
                  and reply["total_iterations"] == 10, "at the cap, a refinement runs no iteration")

        # A drag starts the refinement again from its result.
        ws.send(json.dumps({"type": "drag", "translation": t, "rotation": [math.cos(angle / 2), 0, 0, math.sin(angle / 2)]}))
        reply = ws.reply()
        ws.receive()
        check(reply["type"] == "deformed", "a drag after the refinement is answered")
        ws.send('{"type": "refine"}')
        reply = ws.reply()
        opcode, data = ws.receive()
        positions = struct.unpack(f"<{3 * len(region)}f", data)
        check(reply["type"] == "refined" and reply["total_iterations"] == reply["iterations"] == 4
              and reply["energy_start"] == reply["energy_before"] > last["energy_after"],
              f"a drag starts the refinement again (energy {reply['energy_start']:.4e})")
        check(turned_handle_error(positions) < 1e-3 * radius, "the handle is still on its targets")

        ws.send('{"type": "reset"}')
        reply = ws.reply()
        opcode, data = ws.receive()
        positions = struct.unpack(f"<{3 * len(region)}f", data)
        reset_error = max(abs(positions[3 * j + k] - rest[3 * v + k]) for j, v in enumerate(region) for k in range(3))
        check(reply["type"] == "deformed" and reset_error == 0, "reset restores the rest positions")

        ws.send('{"type": "save"}')
        reply = ws.reply()
        opcode, data = ws.receive()
        check(reply["type"] == "off" and data.startswith(b"OFF") and len(data) == reply["bytes"], "save returns OFF text")
        ws.sock.close()
        check(server.poll() is None, "the server is still running")
    finally:
        server.kill()
        server.wait()
    print(f"{len(failures)} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
