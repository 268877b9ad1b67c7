#!/usr/bin/env bash
# Every program refuses an unknown flag with exit code 2, the flag's name and its usage on stderr,
# and answers --help and -h with its usage on stdout and exit code 0: each semnav_executable (the
# list comes from CMake, so a new binary is checked without editing this file), the launcher's
# and semnavctl's subcommands, and the Node dashboard proxy.
# Usage: unknown_flags_test.sh BIN_DIR NODE DASHBOARD_JS BINARY...
set -uo pipefail
bin_dir=$1
node=$2
dashboard_js=$3
shift 3
binaries=("$@")
# A program that ignored the flag would go on to serve or benchmark: stop it and count a failure.
limit_s=30
out=$(mktemp -d "${TMPDIR:-/tmp}/semnav-unknown-flags.XXXXXX")
trap 'rm -rf "$out"' EXIT
# Programs that write files by default write them here, not in the build folder.
cd "$out" || exit 1
failures=0
checks=0

# expect CODE STREAM TEXT COMMAND...: COMMAND exits with CODE and prints TEXT on STREAM.
expect() {
  local code=$1 stream=$2 text=$3
  shift 3
  checks=$((checks + 1))
  timeout -k 5 "$limit_s" "$@" </dev/null >"$out/stdout" 2>"$out/stderr"
  local got=$?
  local problem=""
  if [[ $got -eq 124 || $got -eq 137 ]]; then
    problem="still running after ${limit_s} s"
  elif [[ $got -ne $code ]]; then
    problem="exit code $got, expected $code"
  elif ! grep -qiF -- "$text" "$out/$stream"; then
    problem="'$text' is not in its $stream"
  fi
  if [[ -n $problem ]]; then
    failures=$((failures + 1))
    echo "FAIL: ${*#"$bin_dir/"}: $problem"
    sed 's/^/  stdout: /' "$out/stdout" | head -5
    sed 's/^/  stderr: /' "$out/stderr" | head -5
  fi
}

# refuses COMMAND...: COMMAND --no-such-flag exits 2 and names the flag on stderr, also when a
# value follows it (a mistyped `--episode 40`).
refuses() {
  expect 2 stderr --no-such-flag "$@" --no-such-flag
  expect 2 stderr --no-such-flag "$@" --no-such-flag 40
}

# helps COMMAND...: --help and -h print the usage on stdout and exit 0.
helps() {
  expect 0 stdout usage "$@" --help
  expect 0 stdout usage "$@" -h
}

[[ ${#binaries[@]} -gt 0 ]] || { echo "FAIL: no binaries given"; exit 1; }
for binary in "${binaries[@]}"; do
  if [[ ! -x $bin_dir/$binary ]]; then
    failures=$((failures + 1))
    echo "FAIL: $bin_dir/$binary is not built"
    continue
  fi
  refuses "$bin_dir/$binary"
  expect 2 stderr usage "$bin_dir/$binary" --no-such-flag
  helps "$bin_dir/$binary"
done

# A flag without its value is refused the same way.
[[ -x $bin_dir/semnav-bench-mission ]] && expect 2 stderr "--seed" "$bin_dir/semnav-bench-mission" --seed
[[ -x $bin_dir/semnav-mapping ]] && expect 2 stderr "--config" "$bin_dir/semnav-mapping" --config

if [[ -x $bin_dir/semnav ]]; then
  refuses "$bin_dir/semnav" up
  refuses "$bin_dir/semnav" up --sim-robot
  refuses "$bin_dir/semnav" status
  helps "$bin_dir/semnav" up
  helps "$bin_dir/semnav" status
  refuses "$bin_dir/semnav" demo
  refuses "$bin_dir/semnav" probe --addr 127.0.0.1:1
  # `semnav bench AREA` execs semnav-bench-AREA with the rest of the line.
  for binary in "${binaries[@]}"; do
    [[ $binary == semnav-bench-* ]] && refuses "$bin_dir/semnav" bench "${binary#semnav-bench-}"
  done
fi

if [[ -x $bin_dir/semnavctl ]]; then
  refuses "$bin_dir/semnavctl"
  refuses "$bin_dir/semnavctl" task list
  refuses "$bin_dir/semnavctl" health
  expect 2 stderr "Usage: semnavctl task list" "$bin_dir/semnavctl" task list --no-such-flag
fi

refuses "$node" "$dashboard_js"
expect 2 stderr usage "$node" "$dashboard_js" --no-such-flag
helps "$node" "$dashboard_js"

echo "$checks checks, $failures failed"
[[ $failures -eq 0 ]]
