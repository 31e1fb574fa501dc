// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Debian's Chromium, headless, driven by puppeteer-core from the npm packages
// installed into a build directory (scripts/install_viewer_web.sh): shared
// by the browser test and the viewer benchmark.
import { createRequire } from 'node:module';
import path from 'node:path';

export const VIEWPORT = { width: 1200, height: 800 };

export function launchChromium(packages) {
  const require = createRequire(path.resolve(packages, 'package.json'));
  const puppeteer = require('puppeteer-core');
  return puppeteer.launch({
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    // WebGL without a GPU: SwiftShader, which Chromium only enables when asked.
    args: ['--no-sandbox', '--headless=new', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
           `--window-size=${VIEWPORT.width},${VIEWPORT.height}`],
    defaultViewport: VIEWPORT,
  });
}
