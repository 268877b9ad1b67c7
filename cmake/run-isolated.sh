#!/bin/sh
# Runs one test process with its own temporary folder: ctest runs test cases in parallel
# processes, and fixed names under a shared /tmp would make them overwrite each other.
dir=$(mktemp -d "${TMPDIR:-/tmp}/semnav-test.XXXXXX") || exit 1
TEST_TMPDIR="$dir/" TMPDIR="$dir" "$@"
rc=$?
rm -rf "$dir"
exit $rc
