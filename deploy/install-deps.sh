#!/usr/bin/env bash
# Installs exactly the Debian 12 packages semnav builds, runs and tests with.
# Idempotent and quiet: packages already present are not fetched again.
set -euo pipefail

packages=(
  # toolchain
  g++ cmake ninja-build ccache pkg-config git
  # the fuzz preset's compiler and libFuzzer (tests/fuzz, docs/dev/fuzzing.md)
  clang-14 libfuzzer-14-dev libclang-rt-14-dev
  # the format check (tests/format/check_format.sh)
  clang-format-14
  # contracts and transport
  libgrpc++-dev protobuf-compiler-grpc libprotobuf-dev protobuf-compiler grpc-proto libabsl-dev
  # algorithms
  libeigen3-dev liboctomap-dev libompl-dev
  libopencv-core-dev libopencv-imgproc-dev libopencv-imgcodecs-dev libopencv-dnn-dev
  # config, text, HTTP
  libyaml-cpp-dev nlohmann-json3-dev libicu-dev libcurl4-openssl-dev libcpp-httplib-dev
  # tests and benchmarks
  libgtest-dev libgmock-dev libbenchmark-dev python3 python3-onnx python3-numpy python3-yaml
  iproute2 openssl
  # contract tooling from npm (buf, grpc-js)
  nodejs
  chromium  # headless browser of the dashboard end-to-end test (playwright-core drives it)
)
# A machine whose nodejs already bundles npm (e.g. NodeSource) must not get Debian's npm on top.
command -v npm >/dev/null 2>&1 || packages+=(npm)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if ((${#missing[@]})); then
  sudo_cmd=()
  [[ $(id -u) -ne 0 ]] && sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# npm tools pinned to exact versions in package.json and package-lock.json (buf for proto lint).
# `npm install --no-save` rather than `npm ci`: npm 11's ci rejects a lock file that lists only
# this platform's optional buf binary; install honours the lock and never rewrites it.
repo_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
(cd "$repo_root" && npm install --no-save --no-audit --no-fund --loglevel=error >/dev/null)
