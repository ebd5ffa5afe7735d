#!/usr/bin/env bash
# Builds the workspace test binaries once, copies them aside (so edits made
# meanwhile cannot change what runs), then runs every test binary of the
# workspace RUNS times (a fresh process each run, from its package
# directory, as `cargo test` does) and prints a pass/fail summary.
# Doc tests are run once at the end with `cargo test --workspace --doc`.
# Usage: scripts/test-20-runs.sh [RUNS]   (default 20; honours CARGO_TARGET_DIR)
set -u
RUNS=${1:-20}
LOGDIR=${LOGDIR:-$(mktemp -d -t pdesculpt-20-runs.XXXXXX)}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
echo "building the test binaries once (log: $LOGDIR/build.log)..."
if ! cargo test --workspace --no-run --message-format=json >"$LOGDIR/build.json" 2>"$LOGDIR/build.log"; then
    echo "build failed; see $LOGDIR/build.log"
    exit 1
fi
# "executable<TAB>package directory" of every test binary
python3 - "$LOGDIR/build.json" >"$LOGDIR/tests.tsv" <<'PY'
import json, os, sys
for line in open(sys.argv[1]):
    try:
        m = json.loads(line)
    except ValueError:
        continue
    if m.get("reason") == "compiler-artifact" and m.get("profile", {}).get("test") and m.get("executable"):
        print(m["executable"] + "\t" + os.path.dirname(m["manifest_path"]))
PY
mkdir -p "$LOGDIR/bin"
n=0
while IFS=$'\t' read -r exe dir; do
    n=$((n + 1))
    cp "$exe" "$LOGDIR/bin/$n-$(basename "$exe")"
    printf '%s\t%s\n' "$LOGDIR/bin/$n-$(basename "$exe")" "$dir"
done <"$LOGDIR/tests.tsv" >"$LOGDIR/snapshot.tsv"
echo "$n test binaries"
pass=0
fail=0
for i in $(seq 1 "$RUNS"); do
    start=$(date +%s)
    ok=1
    : >"$LOGDIR/run-$i.log"
    while IFS=$'\t' read -r exe dir; do
        if ! (cd "$dir" && "$exe") >>"$LOGDIR/run-$i.log" 2>&1; then
            ok=0
        fi
    done <"$LOGDIR/snapshot.tsv"
    counts=$(grep -Eo '^test result: [a-zA-Z]+\. [0-9]+ passed; [0-9]+ failed' "$LOGDIR/run-$i.log" |
        awk '{p += $4; f += $6} END {printf "%d passed, %d failed", p, f}')
    if [ "$ok" -eq 1 ]; then
        pass=$((pass + 1))
        echo "run $i/$RUNS: pass ($counts, $(($(date +%s) - start)) s)"
    else
        fail=$((fail + 1))
        echo "run $i/$RUNS: FAIL ($counts, $(($(date +%s) - start)) s; log $LOGDIR/run-$i.log)"
    fi
done
if cargo test --workspace --doc >"$LOGDIR/doc.log" 2>&1; then
    echo "doc tests: pass"
else
    echo "doc tests: FAIL (log $LOGDIR/doc.log)"
    fail=$((fail + 1))
fi
echo "summary: $pass of $RUNS runs passed, $fail failed (logs in $LOGDIR)"
[ "$fail" -eq 0 ]
