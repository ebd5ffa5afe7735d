#!/usr/bin/env bash
# NaN injection (issue 31): for each equation family, make one core
# evaluation return NaN and require that the family's verify checks fail.
#
#   scripts/nan_inject.sh [FAMILY...]      (default: all seven)
#
# Each injection is one statement, `return <NaN>;`, put at the top of the
# function below (in a scratch copy of the tree; the checkout is never
# touched). The oracle is the same as scripts/mutants.sh's: the family's
# checks in the library's unit-test binary (src/verify/mutants_oracle.rs). A family
# passes this test when the oracle FAILS with the NaN in place and the same
# build without it passed (scripts/mutants.sh's baseline). Shares the
# scratch copy and its target/ with scripts/mutants.sh: do not run both at
# once. Runs outside CI.
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
scratch="${MUTANTS_SCRATCH:-/tmp/pdesculpt-mutants}"

# family | file | function signature start | poison statement
injections() {
  cat <<'EOF'
jet|src/jet/elementary.rs|pub fn sin(&self) -> Self|return Self::constant(f64::NAN);
gec|src/curve/gec/mod.rs|pub fn eval_plane<T: Real>(&self, theta: T) -> [T; 2]|return [theta * f64::NAN; 2];
pde4|src/pde4/two_sided/mode.rs|pub fn eval<T: Real>(&self, u: T) -> T|return u * f64::NAN;
plate|src/plate/mod.rs|pub fn disk_solution<T: Real>(q: f64, rigidity: f64, u: T, v: T) -> T|return u * f64::NAN;
pde6|src/pde6/mode.rs|pub fn eval<T: Real>(&self, u: T) -> [T; 6]|return [u * f64::NAN; 6];
ode6|src/ode6/basis/mod.rs|pub fn g<T: Real>(&self, u: T) -> [T; 6]|return [u * f64::NAN; 6];
conv|src/conv/kernel.rs|pub fn f1<T: Real>(h: T, q: T, l: f64, s: f64) -> T|return h * f64::NAN;
EOF
}

families=("$@")
[ ${#families[@]} -eq 0 ] && families=(jet gec pde4 plate pde6 ode6 conv)

mkdir -p "$scratch/target/debug"
# one job at a time on the scratch copy (scripts/mutants.sh takes the same
# lock)
exec 9>"$scratch.lock"
if ! flock -n 9; then
  echo "another mutation or NaN-injection job is using $scratch; wait for it" >&2
  exit 2
fi
export CARGO_TARGET_DIR="$scratch/target"
status=0
for fam in "${families[@]}"; do
  line="$(injections | grep "^$fam|" || true)"
  [ -n "$line" ] || { echo "unknown family $fam" >&2; exit 2; }
  IFS='|' read -r _ file sig poison <<<"$line"
  rm -rf "$scratch/src" && mkdir -p "$scratch/src"
  tar -C "$root" --exclude=./target --exclude=./mutants.out --exclude=./.git -cf - . | tar -C "$scratch/src" -xf -
  python3 - "$scratch/src/$file" "$sig" "$poison" <<'PY'
import sys
path, sig, poison = sys.argv[1:]
s = open(path).read()
k = s.find(sig)
if k < 0:
    sys.exit(f"signature not found in {path}: {sig}")
brace = s.index("{", k + len(sig))
s = s[:brace + 1] + "\n    " + poison + "\n" + s[brace + 1:]
open(path, "w").write(s)
PY
  echo "== $fam: $file: $sig { $poison ... }" >&2
  if (cd "$scratch/src" && PDESCULPT_MUTANTS_FAMILY="$fam" nice -n 10 cargo test --lib -q \
        -- --include-ignored mutants_oracle >"$scratch/nan_$fam.log" 2>&1); then
    echo "$fam: NOT DETECTED (the family's checks passed with NaN injected)"
    status=1
  elif grep -q "failing checks:" "$scratch/nan_$fam.log"; then
    failed="$(grep -c '(measured NaN' "$scratch/nan_$fam.log" || true)"
    echo "$fam: detected ($failed checks fail with measured NaN; log $scratch/nan_$fam.log)"
  else
    echo "$fam: ERROR (build or harness failed, not the checks; log $scratch/nan_$fam.log)"
    status=1
  fi
done
exit $status
