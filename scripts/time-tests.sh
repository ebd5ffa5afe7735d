#!/usr/bin/env bash
# Where the time of the test suite and of `pdesculpt verify` goes, as the
# Markdown tables of docs/test-time.md (stdout); progress on stderr.
#
#   scripts/time-tests.sh [OUT_DIR]        (default: a fresh temporary directory)
#
# Steps, each timed with /usr/bin/time (wall, and CPU = user + sys, which a
# loaded machine disturbs less than wall):
#   1. `cargo build --release` and `cargo test --workspace --no-run` (warm
#      when nothing changed: the build's own time is `cargo build --timings`);
#   2. `cargo test --workspace` on the warm build (the README's command);
#   3. `cargo nextest run --workspace` for per-test times (each test in its
#      own process: fixtures shared through a OnceLock are paid by every
#      test that uses them, so the per-test numbers are upper bounds);
#   4. `pdesculpt verify --json` whole, then per family, in release.
# The lists of test names and check names go to OUT_DIR (tests.txt,
# checks.txt) so that two runs can be diffed (docs/test-time.md).
# Set SKIP_CARGO_TEST=1 or SKIP_NEXTEST=1 to leave a step out.
set -uo pipefail
cd "$(dirname "$0")/.."
OUT=${1:-$(mktemp -d -t pdesculpt-time.XXXXXX)}
mkdir -p "$OUT"
log() { echo "time-tests: $*" >&2; }
# timed LOG CMD...: runs CMD under /usr/bin/time with its stdout and
# stderr in LOG (a file or /dev/null); prints "wall cpu" (seconds) to stdout
timed() {
    local tf log=$1
    shift
    tf=$(mktemp)
    /usr/bin/time -f "%e %U %S" -o "$tf" "$@" >"$log" 2>&1
    local rc=$?
    awk '{printf "%.1f %.1f\n", $1, $2 + $3}' "$tf"
    rm -f "$tf"
    return $rc
}
export CARGO_TERM_COLOR=never

log "building release and the test binaries (output in $OUT)"
read -r rb_wall rb_cpu < <(timed "$OUT/build-release.log" cargo build --release --workspace --bins)
read -r tb_wall tb_cpu < <(timed "$OUT/build-tests.log" cargo test --workspace --no-run)

log "listing tests and checks"
# "binary: test name" (the unit tests of src/lib.rs are binary `pdesculpt`,
# the integration tests `it`, doc tests `doc`)
cargo test --workspace -- --list 2>&1 |
    awk '/^ *Running /{b=$NF; gsub(/.*deps\/|-[0-9a-f]+\)$/, "", b); next}
         /^ *Doc-tests /{b="doc"; next}
         /: (test|benchmark)$/{sub(/: (test|benchmark)$/, ""); print b ": " $0}' |
    sort >"$OUT/tests.txt"
target/release/pdesculpt verify --json >"$OUT/verify.json" 2>/dev/null
python3 - "$OUT/verify.json" >"$OUT/checks.txt" <<'PY'
import json, sys
for c in json.load(open(sys.argv[1]))["checks"]:
    print(f'{c["family"]}\t{c["name"]}')
PY

echo "# Test and verify timings ($(date -u +%Y-%m-%d), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg) at the start)"
echo
echo "Made by \`scripts/time-tests.sh\` at commit $(git rev-parse --short HEAD)."
echo
echo "| step | wall s | CPU s |"
echo "|---|---:|---:|"
echo "| cargo build --release --workspace --bins (warm) | $rb_wall | $rb_cpu |"
echo "| cargo test --workspace --no-run (warm) | $tb_wall | $tb_cpu |"

if [ -z "${SKIP_CARGO_TEST:-}" ]; then
    log "cargo test --workspace"
    read -r ct_wall ct_cpu < <(timed "$OUT/cargo-test.log" cargo test --workspace)
    echo "| cargo test --workspace (warm) | $ct_wall | $ct_cpu |"
fi
v_line=$(timed /dev/null target/release/pdesculpt verify --json)
echo "| pdesculpt verify (release, all families) | ${v_line% *} | ${v_line#* } |"
eq_args=()
for f in jet mesh surface derivatives gec pde4 plate pde6 ode6 conv; do eq_args+=(--family "$f"); done
eq_line=$(timed /dev/null target/release/pdesculpt verify "${eq_args[@]}" --json)
echo "| pdesculpt verify, the equation families (jet mesh surface derivatives gec pde4 plate pde6 ode6 conv) | ${eq_line% *} | ${eq_line#* } |"
echo
echo "Verify per family (release, one process each; \`pdesculpt verify --family F --json\`):"
echo
echo "| family | checks | wall s | CPU s |"
echo "|---|---:|---:|---:|"
for f in $(cut -f1 "$OUT/checks.txt" | uniq); do
    n=$(awk -F'\t' -v f="$f" '$1 == f' "$OUT/checks.txt" | wc -l)
    line=$(timed /dev/null target/release/pdesculpt verify --family "$f" --json)
    echo "| $f | $n | ${line% *} | ${line#* } |"
done
echo
echo "$(wc -l <"$OUT/tests.txt") tests, $(wc -l <"$OUT/checks.txt") checks."

if [ -z "${SKIP_NEXTEST:-}" ] && command -v cargo-nextest >/dev/null 2>&1; then
    log "cargo nextest run --workspace (per-test times)"
    read -r nx_wall nx_cpu < <(timed "$OUT/nextest.log" cargo nextest run --workspace --no-fail-fast \
        --success-output never --failure-output final)
    echo
    echo "\`cargo nextest run --workspace\`: $nx_wall s wall, $nx_cpu s CPU. Slowest tests (wall, own process):"
    echo
    echo "| s | test |"
    echo "|---:|---|"
    grep -E '^ +(PASS|FAIL|SIGSEGV|SIGABRT|TIMEOUT) \[' "$OUT/nextest.log" |
        sed -E 's/^ +([A-Z]+) \[ *([0-9.]+)s\] (\([^)]*\) )?(.*)$/\2 \1 \4/' |
        sort -rn | head -25 | awk '{s=$1; st=$2; $1=""; $2=""; sub(/^  /, ""); printf "| %s | %s%s |\n", s, $0, (st == "PASS" ? "" : " (" st ")")}'
    grep -E '^ +(PASS|FAIL) \[' "$OUT/nextest.log" |
        sed -E 's/^ +([A-Z]+) \[ *([0-9.]+)s\] (\([^)]*\) )?(.*)$/\2\t\4/' | sort -rn >"$OUT/per-test.tsv"
    over=$(awk -F'\t' '$1 > 30' "$OUT/per-test.tsv" | wc -l)
    echo
    echo "Tests over 30 s: $over (all per-test times: $OUT/per-test.tsv)."
fi
log "done; lists in $OUT"
