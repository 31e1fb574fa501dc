#!/bin/sh
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# run_installed.sh ENVIRONMENT ARGUMENTS...: runs the Python of the virtual
# environment where scripts/install_python_package.sh installed the package
# ssmd, so that the tests exercise the installed package; says what to do
# when there is none.
environment="$1"
shift
if [ ! -x "$environment/bin/python" ]; then
  echo "no Python environment in $environment: the tests run the installed package;" >&2
  echo "install it with scripts/install_python_package.sh" >&2
  exit 1
fi
exec "$environment/bin/python" "$@"
