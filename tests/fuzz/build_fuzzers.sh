#!/usr/bin/env bash
# Configures and builds the fuzz preset (build/fuzz, clang-14) from the release ctest, so the
# README's test command runs the fuzz smoke runs. Only the harnesses and what they link are built.
set -euo pipefail
cd "$1"
cmake --preset fuzz >/dev/null
nice -n 5 cmake --build --preset fuzz
