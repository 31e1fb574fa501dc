#!/usr/bin/env python3
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Opens the HTML manual in headless Chromium and checks what a reader sees.

    check_manual_in_browser.py CHROMIUM HTML_DIR SCREENSHOT_DIR

For the main page and every page with formulas: each formula was typeset by
MathJax (one rendered element per TeX source, no 'Math Processing Error'),
nothing is loaded from the network, and the stylesheet that fits the figures
to the page is linked. Keeps a screenshot of the main page.
"""

import glob
import os
import re
import subprocess
import sys
import tempfile


def chromium(binary, profile, *arguments):
    command = [binary, "--headless=new", "--no-sandbox", "--disable-gpu", "--no-first-run",
               "--user-data-dir=" + profile, "--allow-file-access-from-files",
               "--virtual-time-budget=20000", "--window-size=1200,1600"] + list(arguments)
    return subprocess.run(command, capture_output=True, text=True, timeout=240)


def main():
    binary, html_dir, screenshot_dir = sys.argv[1:4]
    os.makedirs(screenshot_dir, exist_ok=True)
    pages = [os.path.join(html_dir, "index.html")]
    for page in sorted(glob.glob(os.path.join(html_dir, "*.html"))):
        with open(page, encoding="utf-8", errors="replace") as f:
            if "\\(" in f.read() and page not in pages:
                pages.append(page)
    failures = []
    with tempfile.TemporaryDirectory() as profile:
        for page in pages:
            name = os.path.basename(page)
            url = "file://" + os.path.abspath(page)
            dom = chromium(binary, profile, "--dump-dom", url).stdout
            sources = len(re.findall(r'<script type="math/tex', dom))
            rendered = len(re.findall(r'class="MathJax_SVG"', dom)) + \
                len(re.findall(r'class="MathJax_SVG_Display"', dom))
            remote = re.findall(r'<(?:script|link|img)[^>]+(?:src|href)="(https?://[^"]+)"', dom)
            problems = []
            if not dom:
                problems.append("no page")
            if page.endswith("index.html") and sources == 0:
                problems.append("no formula typeset on the main page")
            if rendered < sources:
                problems.append("%d of %d formulas typeset" % (rendered, sources))
            if "Math Processing Error" in dom:
                problems.append("MathJax reported an error")
            if remote:
                problems.append("loads from the network: " + ", ".join(sorted(set(remote))[:3]))
            if "manual.css" not in dom:
                problems.append("the stylesheet manual.css is not linked")
            if name == "index.html":
                chromium(binary, profile, "--screenshot=" + os.path.join(screenshot_dir, "index.png"), url)
            print("%-40s %3d formulas typeset%s" % (name, rendered,
                                                     "" if not problems else ": " + "; ".join(problems)))
            if problems:
                failures.append(name)
    print("screenshot of the main page in", screenshot_dir)
    if failures:
        sys.exit("pages with problems: " + ", ".join(failures))


if __name__ == "__main__":
    main()
