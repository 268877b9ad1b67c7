#!/bin/bash
# Lock-step simulated time (docs/simulation.md, "Time"): an episode is a pure function of its
# inputs. The same 8-episode bench (4 generated homes x 2 starts, SEMANTIC_FRONTIER) runs twice,
# once on two stacks (--jobs 2) while two busy loops keep both cores loaded, once on one stack
# (--jobs 1); the per-episode records must be identical and so must the timelines (object ids
# aside: mapping keeps numbering objects across ResetMap, so they depend on the episodes run
# before on the same stack). Then 3 kidnapped episodes relocalize in mapping's own landmark map
# (--landmarks mapping), loaded and quiet the same way: that map must follow the frames, not a
# push thread's wall-time interval. Last, 3 outdoor episodes per strategy with the simulated VLM in
# the stack (--model sim): its answers, the text encoder's included, take their stated simulated
# time (the encoder's used to take the proxy's wall time), and do not depend on the object ids
# or answers of the episodes run before on the same stack.
# usage: lockstep_determinism_test.sh BIN_DIR
set -u
bin=$1/semnav
work=$(mktemp -d "${TMPDIR:-/tmp}/semnav-lockstep-test.XXXXXX") || exit 1
busy=()
cleanup() {
  for pid in "${busy[@]}"; do kill "$pid" 2>/dev/null; done
  rm -rf "$work"
}
trap cleanup EXIT

run() {  # run NAME JOBS [GROUP FLAGS (a --strategies there wins)]
  local name=$1 jobs=$2
  shift 2
  local groups=("$@")
  [[ ${#groups[@]} == 0 ]] && groups=(--episodes 8)
  "$bin" bench mission --strategies SEMANTIC_FRONTIER "${groups[@]}" --jobs "$jobs" \
    --out "$work/$name" --json "$work/$name.json" >"$work/$name.out" 2>"$work/$name.err"
  local rc=$?
  if [[ $rc != 0 ]]; then
    echo "FAIL: run $name exited $rc"
    tail -n 20 "$work/$name.out" "$work/$name.err"
    exit 1
  fi
}

for _ in 1 2; do
  (while :; do :; done) &
  busy+=($!)
done
kidnapped=(--episodes 0 --kidnapped-episodes 3 --landmarks mapping --max-steps 300)
if ! "$1/semnav-sim-worlds" --out "$work/suite" >"$work/worlds.out" 2>&1; then
  echo "FAIL: semnav-sim-worlds"
  tail -n 20 "$work/worlds.out"
  exit 1
fi
model=(--suite "$work/suite/outdoor" --episodes 0 --outdoor-episodes 3 --model sim --max-steps 80
  --strategies NEAREST_FRONTIER,EROI_UTILITY)
run loaded 2
run kidnapped_loaded 2 "${kidnapped[@]}"
run model_loaded 2 "${model[@]}"
for pid in "${busy[@]}"; do kill "$pid" 2>/dev/null; done
busy=()
run quiet 1
run kidnapped_quiet 1 "${kidnapped[@]}"
run model_quiet 1 "${model[@]}"

python3 - "$work" <<'PY'
import glob, json, os, re, sys
work = sys.argv[1]
failures = []
mask = lambda text: re.sub(r"object \d+", "object N", text)
def compare(loaded, quiet, count):
    a = json.load(open(os.path.join(work, loaded + ".json")))["episodes"]
    b = json.load(open(os.path.join(work, quiet + ".json")))["episodes"]
    if len(a) != count or len(b) != count:
        failures.append("%s: expected %d episode records, got %d and %d" %
                        (loaded, count, len(a), len(b)))
    for i, (x, y) in enumerate(zip(a, b)):
        if x != y:
            failures.append("%s: episode %d differs:\n  loaded %s\n  quiet  %s" % (loaded, i, x, y))
    logs = sorted(os.path.basename(p) for p in glob.glob(os.path.join(work, loaded, "*.log")))
    if len(logs) != count:
        failures.append("%s: expected %d timelines, got %d" % (loaded, count, len(logs)))
    for name in logs:
        x = mask(open(os.path.join(work, loaded, name)).read())
        y = mask(open(os.path.join(work, quiet, name)).read())
        if x != y:
            xs, ys = x.splitlines(), y.splitlines()
            first = next((i for i in range(min(len(xs), len(ys))) if xs[i] != ys[i]),
                         min(len(xs), len(ys)))
            failures.append("timeline %s/%s differs at line %d:\n  loaded %s\n  quiet  %s" %
                            (loaded, name, first + 1, xs[first] if first < len(xs) else "<end>",
                             ys[first] if first < len(ys) else "<end>"))
    return a
a = compare("loaded", "quiet", 8)
k = compare("kidnapped_loaded", "kidnapped_quiet", 3)
m = compare("model_loaded", "model_quiet", 6)
if failures:
    print("FAIL:\n" + "\n".join(failures))
    sys.exit(1)
print("8 episodes identical on 2 loaded stacks and 1 quiet stack; SR %.3f" %
      (sum(e["success"] for e in a) / len(a)))
print("3 kidnapped episodes identical; %d losses, %d corrections" %
      (sum(e["losses"] for e in k), sum(len(e["recovery_times_s"]) for e in k)))
print("6 outdoor episodes with the simulated VLM identical; %d model calls" %
      sum(e["model_calls"] for e in m))
PY
