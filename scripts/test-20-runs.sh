#!/usr/bin/env bash
# Builds the test binaries once, then runs the whole workspace test suite
# 20 times (a fresh process each run) and prints a pass/fail summary.
# Usage: scripts/test-20-runs.sh [RUNS]   (default 20)
# Set CARGO_TARGET_DIR as usual; a log per run goes to $LOGDIR (default a
# temporary directory).
set -u
RUNS=${1:-20}
LOGDIR=${LOGDIR:-$(mktemp -d -t pdesculpt-20-runs.XXXXXX)}
cd "$(dirname "$0")/.."
echo "building the test binaries once..."
if ! cargo test --workspace --no-run >"$LOGDIR/build.log" 2>&1; then
    echo "build failed; see $LOGDIR/build.log"
    exit 1
fi
pass=0
fail=0
for i in $(seq 1 "$RUNS"); do
    start=$(date +%s)
    if cargo test --workspace >"$LOGDIR/run-$i.log" 2>&1; then
        pass=$((pass + 1))
        status=pass
    else
        fail=$((fail + 1))
        status=FAIL
    fi
    tests=$(grep -Eo '^test result: [a-zA-Z]+\. [0-9]+ passed; [0-9]+ failed' "$LOGDIR/run-$i.log" |
        awk '{p += $4; f += $6} END {printf "%d passed, %d failed", p, f}')
    echo "run $i/$RUNS: $status ($tests, $(( $(date +%s) - start )) s)"
done
echo "summary: $pass of $RUNS runs passed, $fail failed (logs in $LOGDIR)"
[ "$fail" -eq 0 ]
