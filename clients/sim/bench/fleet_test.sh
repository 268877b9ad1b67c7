#!/bin/bash
# A short fleet run (3 robots, 10 s) against one real stack: it completes with 0 errors, writes
# every key the issue asks for, with plausible numbers (latencies > 0 and finite, RSS > 0).
# usage: fleet_test.sh BIN_DIR
set -u
bin=$1/semnav-bench-fleet
work=$(mktemp -d "${TMPDIR:-/tmp}/semnav-fleet-test.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT

"$bin" --robots 3 --duration-s 10 --json "$work/fleet.json" >"$work/out" 2>"$work/err"
rc=$?
cat "$work/out"
if [[ $rc != 0 ]]; then
  echo "FAIL: exit $rc"
  cat "$work/err"
  exit 1
fi
grep -Eq '^  3 robots +10 s \| command p50 [0-9.]+ p99 [0-9.]+ ms' "$work/out" || {
  echo "FAIL: no result line for 3 robots"
  exit 1
}
python3 - "$work/fleet.json" <<'PY'
import json, math, sys
run = json.load(open(sys.argv[1]))
failures = []
def check(ok, what):
    if not ok:
        failures.append(what)
for key in ["robots", "command_ms_p50", "command_ms_p99", "operator_ms_p99", "errors",
            "rss_growth_pct", "max_robots_meeting_targets", "services",
            "instruction_to_command_ms_p99", "feedback_to_command_ms_p99"]:
    check(key in run, "no key " + key)
if not failures:
    positive = lambda v: isinstance(v, (int, float)) and math.isfinite(v) and v > 0
    check(run["robots"] == 3, "robots %r, not 3" % run["robots"])
    check(run["errors"] == 0, "errors %r: %r" % (run["errors"], run.get("error_samples")))
    # Every robot got its task's first command; the operator polled every task.
    check(run["instruction_to_command_samples"] >= 3,
          "fewer than 3 instruction -> command samples")
    check(run["operator_samples"] >= 3 * 10, "fewer than 30 GetTask samples")
    for key in ["command_ms_p50", "command_ms_p99", "operator_ms_p99",
                "instruction_to_command_ms_p99"]:
        check(positive(run[key]) and run[key] < 10000, "%s = %r" % (key, run[key]))
    check(run["command_ms_p50"] <= run["command_ms_p99"], "command p50 above p99")
    check(set(run["services"]) == {"gateway", "mapping", "planning"},
          "services %r" % sorted(run["services"]))
    for name, rss in run["services"].items():
        for key in ["rss_start_kb", "rss_warm_kb", "rss_end_kb"]:
            check(rss[key] > 0, "%s %s = %r" % (name, key, rss[key]))
    check(math.isfinite(run["rss_growth_pct"]), "rss_growth_pct not finite")
    meeting = run["max_robots_meeting_targets"]
    check(meeting in (0, 3), "max_robots_meeting_targets %r" % meeting)
    check((meeting == 3) == run["meets_targets"], "max_robots_meeting_targets disagrees")
for f in failures:
    print("FAIL: " + f)
sys.exit(1 if failures else 0)
PY
[[ $? == 0 ]] && echo "ok: semnav-bench-fleet" || exit 1
