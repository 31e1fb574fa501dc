#!/usr/bin/env python3
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs a command with its standard error on a pseudo-terminal of a given
# size, or on a log file, and checks the progress it prints there.
#
# usage: check_progress.py --terminal COLUMNS [--columns-env N] -- COMMAND...
#        check_progress.py --log -- COMMAND...
#
# --terminal: standard error is a pseudo-terminal COLUMNS wide (0: a
#   terminal that reports no size; --columns-env then sets $COLUMNS). The
#   output is replayed on a model of the terminal: nothing may reach the
#   last column (that would wrap, or wrap on some terminals), a progress bar
#   must have been drawn, and none of it may be left on the screen at the end.
# --log: standard error is a regular file; it must hold plain progress lines
#   ("basis: 40% (48 of ~120 solves), 0.1 s"), at least two, and no control
#   character.
# Standard output goes to a pipe and is printed, with the exit status, which
# must be 0.
import argparse
import fcntl
import os
import re
import struct
import subprocess
import sys
import tempfile
import termios

ESCAPE = re.compile(r"\x1b\[([0-9;]*)([A-Za-z])")
LOG_LINE = re.compile(r"^basis: [0-9]+% \([0-9]+ of ~[0-9]+ solves\), [0-9.]+ (s|min [0-9]+ s)$")


def run_on_terminal(command, columns, environment):
    master, slave = os.openpty()
    fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", 24, columns, 0, 0))
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=slave, env=environment)
    os.close(slave)
    chunks = []
    while True:
        try:
            chunk = os.read(master, 65536)
        except OSError:  # EIO: the last writer closed the terminal
            break
        if not chunk:
            break
        chunks.append(chunk)
    stdout = process.stdout.read()
    status = process.wait()
    os.close(master)
    return status, stdout.decode(errors="replace"), b"".join(chunks).decode(errors="replace")


def replay(output, columns):
    """The screen after `output`, and the problems found on the way."""
    problems = []
    screen = [[]]
    column = 0
    position = 0
    while position < len(output):
        character = output[position]
        match = ESCAPE.match(output, position)
        if match:
            if match.group(2) != "K":
                problems.append("unexpected escape sequence %r" % match.group(0))
            del screen[-1][column:]
            position = match.end()
            continue
        position += 1
        if character == "\r":
            column = 0
        elif character == "\n":
            screen.append([])
            column = 0
        elif character < " ":
            problems.append("control character %r" % character)
        else:
            if column >= columns - 1:
                problems.append("a line reaches column %d of %d: %r"
                                % (column + 1, columns, "".join(screen[-1])))
            line = screen[-1]
            line.extend(" " * (column + 1 - len(line)))
            line[column] = character
            column += 1
    return ["".join(line) for line in screen], problems


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--terminal", type=int, metavar="COLUMNS")
    parser.add_argument("--columns-env", type=int)
    parser.add_argument("--log", action="store_true")
    parser.add_argument("command", nargs=argparse.REMAINDER)
    arguments = parser.parse_args()
    command = arguments.command[1:] if arguments.command[:1] == ["--"] else arguments.command
    environment = dict(os.environ)
    environment.pop("COLUMNS", None)
    if arguments.columns_env is not None:
        environment["COLUMNS"] = str(arguments.columns_env)

    problems = []
    if arguments.terminal is not None:
        status, stdout, stderr = run_on_terminal(command, arguments.terminal, environment)
        width = arguments.terminal or arguments.columns_env or 80
        print(stdout, end="")
        print("[standard error, on a terminal of %d columns]" % width)
        print(repr(stderr))
        screen, problems = replay(stderr, width)
        if "\r" not in stderr or "%" not in stderr:
            problems.append("no progress bar was drawn")
        left = [line for line in screen if "basis" in line]
        if left:
            problems.append("the progress bar was not erased: %r" % left)
    else:
        with tempfile.TemporaryFile() as log:
            status = subprocess.call(command, stdout=sys.stdout, stderr=log, env=environment)
            log.seek(0)
            stderr = log.read().decode(errors="replace")
        print("[standard error, on a file]")
        print(stderr, end="")
        lines = [line for line in stderr.split("\n") if LOG_LINE.match(line)]
        if len(lines) < 2:
            problems.append("fewer than two progress lines")
        if re.search(r"[\x00-\x09\x0b-\x1f]", stderr):
            problems.append("a control character in the log")
    print("[exit status %d]" % status)
    if status != 0:
        problems.append("expected exit status 0")
    for problem in problems:
        print("FAILED: " + problem)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
