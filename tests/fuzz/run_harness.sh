#!/usr/bin/env bash
# run_harness.sh <fuzzer binary> <seed corpus dir> <regressions dir> <seconds>
# Replays every saved crash input once, then fuzzes for <seconds> from the seeds. New corpus
# entries go to a scratch folder (the committed corpus is never written); a crash leaves its
# input in the scratch folder, whose path is printed, to be copied into the regressions folder.
set -euo pipefail
binary=$(realpath "$1") corpus=$(realpath -m "$2") regressions=$(realpath -m "$3") seconds=$4
name=$(basename "$binary")
scratch=$(mktemp -d "${TMPDIR:-/tmp}/${name}.XXXXXX")
cd "$scratch"  # harnesses that write files do it under their own temp folders; artifacts land here

# The sanitizers stop at the first error. Leak checks stay on, except for the RPC harnesses:
# gRPC's threads allocate while an input runs, which libFuzzer's per-input leak check would
# blame on the input.
leaks=1
[[ $name == fuzz_rpc_* ]] && leaks=0
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=$leaks:allocator_may_return_null=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}

shopt -s nullglob
saved=("$regressions"/*)
if ((${#saved[@]})); then
  echo "== replaying ${#saved[@]} regression input(s) from $regressions"
  "$binary" -rss_limit_mb=2048 -timeout=20 "${saved[@]}"
fi

mkdir -p "$scratch/corpus"
# A fixed seed by default, so a CI run explores the same inputs each time and a new finding is
# reproducible; SEMNAV_FUZZ_SEED=0 picks a random one (longer runs, docs/dev/fuzzing.md).
seed=${SEMNAV_FUZZ_SEED:-1}
echo "== fuzzing $name for ${seconds}s from $corpus (seed $seed, scratch: $scratch)"
if ! "$binary" -seed="$seed" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
    -print_final_stats=1 -artifact_prefix="$scratch/" "$scratch/corpus" $([[ -d $corpus ]] && echo "$corpus"); then
  echo "FUZZ FAILURE in $name: the input is in $scratch (crash-*/leak-*/timeout-*/oom-*)."
  echo "Fix it, then keep the input: cp $scratch/<file> $regressions/"
  exit 1
fi
rm -rf "$scratch"
