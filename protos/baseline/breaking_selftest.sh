#!/bin/sh
# Proves the buf_breaking test can fail: on a scratch copy of protos/, deleting a v1 field must
# make `buf breaking` against the baseline exit non-zero and name the field, while adding a
# field (an allowed, additive change) must pass. Usage: breaking_selftest.sh <buf>
set -eu
buf=$1
protos=$(cd "$(dirname "$0")/.." && pwd)
scratch=$(mktemp -d "${TMPDIR:-/tmp}/semnav-breaking.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
against="$protos/baseline/semnav-v1.binpb"
errors=semnav/common/v1/errors.proto

copy() {
  rm -rf "$scratch/protos"
  cp -r "$protos" "$scratch/protos"
}

# ErrorInfo.reason is part of v1: every client switches on it.
copy
grep -q '^  string reason = 1;$' "$scratch/protos/$errors"
sed -i '/^  string reason = 1;$/d' "$scratch/protos/$errors"
if (cd "$scratch/protos" && "$buf" breaking --against "$against") >"$scratch/out" 2>&1; then
  echo "FAIL: deleting ErrorInfo.reason was not reported as breaking"; exit 1
fi
grep -q 'deleted' "$scratch/out" && grep -q 'reason' "$scratch/out" || { cat "$scratch/out"; echo "FAIL: unexpected report"; exit 1; }
echo "ok: deleting ErrorInfo.reason is breaking:"; cat "$scratch/out"

# A new field with a new number is compatible.
copy
sed -i 's/^  string reason = 1;$/  string reason = 1;\n  \/\/ Added by the self-test.\n  string added_by_selftest = 99;/' "$scratch/protos/$errors"
grep -q 'added_by_selftest = 99' "$scratch/protos/$errors"
(cd "$scratch/protos" && "$buf" breaking --against "$against") || { echo "FAIL: an added field was reported as breaking"; exit 1; }
echo "ok: adding a field is not breaking"
