#!/bin/bash
# `semnav demo` end to end: the search episode succeeds (exit 0), prints its progress and the
# result line, and writes demo.md and demo.png; bad flags exit 2 with the usage on stderr.
# usage: demo_test.sh BIN_DIR
set -u
bin=$1/semnav-sim-demo
work=$(mktemp -d "${TMPDIR:-/tmp}/semnav-demo-test.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT
failures=0
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}

"$bin" --out "$work/report" >"$work/out" 2>"$work/err"
rc=$?
cat "$work/out"
[[ $rc == 0 ]] || fail "exit $rc, not 0 (success)"
grep -q '^world demo_home_11, start 0, instruction "find a bed"' "$work/out" || fail "no episode line"
grep -q 'no bed$' "$work/out" && grep -q '^  is in sight from the start at' "$work/out" ||
  fail "no out-of-sight line"
grep -Eq '^  t= *[0-9.]+s  (exploring|looking_around) ' "$work/out" || fail "no progress line while exploring"
grep -q 'the camera sees a bed' "$work/out" || fail "the target was never reported seen"
grep -Eq '^SUCCESS after [0-9]+ steps .*: SR 1, SPL 0\.[0-9]+, path [0-9.]+ m, shortest 4\.33 m, .*model calls [0-9]+' \
  "$work/out" || fail "no result line with SR, SPL, path, shortest path and model calls"
grep -q "^report: $work/report/demo.md and $work/report/demo.png" "$work/out" || fail "no report line"
grep -q '^| ' "$work/report/demo.md" || fail "demo.md has no result table"
[[ $(head -c 8 "$work/report/demo.png" | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]] ||
  fail "demo.png is not a PNG"

"$bin" --no-such-flag >"$work/bad.out" 2>"$work/bad.err"
rc=$?
[[ $rc == 2 ]] || fail "an unknown flag exits $rc, not 2"
grep -q '^usage: semnav-sim-demo' "$work/bad.err" || fail "an unknown flag prints no usage on stderr"
[[ ! -s "$work/bad.out" ]] || fail "an unknown flag prints on stdout"
"$bin" --help >"$work/help.out" 2>&1
rc=$?
[[ $rc == 0 ]] && grep -q -- '--world-seed N' "$work/help.out" || fail "--help exits $rc or lacks the flags"

[[ $failures == 0 ]] && echo "ok: semnav-sim-demo" || exit 1
