#!/usr/bin/env bash
# Sets up the machine, builds everything with the tests, and runs the whole test suite with ctest.
# Extra arguments go to cmake (CI passes -DFEATURERECON_WARNINGS_AS_ERRORS=ON).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
BUILD_DIR=${BUILD_DIR:-build} bash scripts/build.sh -DFEATURERECON_BUILD_TESTS=ON -DFEATURERECON_BUILD_EXAMPLES=ON "$@"
cd "${BUILD_DIR:-build}"
# A test that hangs fails after 10 minutes instead of holding the run (the slowest takes under a minute).
ctest --output-on-failure --parallel "$(nproc)" --timeout 600
