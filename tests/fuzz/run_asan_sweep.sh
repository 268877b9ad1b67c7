#!/usr/bin/env bash
# run_asan_sweep.sh <bin dir of the fuzz build>: the request sweep, built with ASan and UBSan,
# against that build's (sanitized) service binaries. Any sanitizer report in a service aborts it,
# which the sweep sees as a dead service.
set -euo pipefail
export ASAN_OPTIONS=${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
exec "$1/semnav_request_sweep_contract_test"
