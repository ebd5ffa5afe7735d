#!/usr/bin/env bash
# Mutation testing of the equation families' core files (issue 31).
#
#   scripts/mutants.sh FAMILY [--list] [--shard K/N] [extra cargo-mutants args]
#
# FAMILY is one of: jet gec pde4 plate pde6 ode6 conv. The oracle is the
# family's verify checks (`src/verify/mutants_oracle.rs`, the same checks as
# `pdesculpt verify --family FAMILY`) plus the family's own unit tests in the
# library, all in the library's unit-test binary, so each mutant costs one
# incremental dev-profile build of the library in test mode
# (`--cargo-arg=--lib` reaches cargo-mutants' build phase, `cargo test
# --no-run`, as well as the test phase: without it every mutant built the
# integration tests and the examples too). Integration
# tests (tests/it) are left out of the oracle: each mutant would relink that
# 15k-line binary, and CPU on the shared machine does not allow it.
#
# Needs cargo-mutants (`cargo install cargo-mutants --locked`). Runs outside
# CI. One job at a time (--in-place), nice. Results go to mutants.out/FAMILY/ (not
# committed); docs/verification.md holds the table.
#
# cargo-mutants runs --in-place in a scratch copy of the tree at a stable
# path ($MUTANTS_SCRATCH, default /tmp/pdesculpt-mutants), so that successive
# mutants and families rebuild incrementally; its target/ is seeded with
# hard links to this checkout's compiled dependencies (no disk copy, no
# dependency rebuild). The copy is refreshed from the working tree on every
# run (tar; target/, mutants.out/ and .git/ excluded).
set -euo pipefail

family="${1:?usage: scripts/mutants.sh FAMILY [--list] [cargo-mutants args]}"
shift

root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"

skip=()
case "$family" in
  jet) files=(src/jet/mod.rs src/jet/elementary.rs src/jet/real.rs)
       filter="jet::" ;;
  gec) files=(src/curve/gec/mod.rs src/curve/gec/fit.rs src/curve/gec/lsq.rs src/curve/gec/metrics.rs)
       filter="curve::gec::" ;;
  pde4) files=(src/pde4/two_sided/mode.rs src/pde4/two_sided/mod.rs src/pde4/force.rs src/pde4/four_sided.rs)
        filter="pde4::" ;;
  plate) files=(src/plate/mod.rs src/plate/projection.rs src/plate/mapping.rs)
         # "plate::" also matches template:: tests (one is an ignored,
         # failing test, which made every plate mutant look caught)
         filter="plate::"; skip=(--skip template::) ;;
  pde6) files=(src/pde6/mode.rs src/pde6/patch.rs)
        filter="pde6::" ;;
  ode6) files=(src/ode6/basis/mod.rs src/ode6/basis/roots.rs src/ode6/basis/case_basis.rs)
        filter="ode6::" ;;
  conv) files=(src/conv/kernel.rs src/conv/fit.rs)
        filter="conv::" ;;
  *) echo "unknown family '$family' (jet gec pde4 plate pde6 ode6 conv)" >&2; exit 2 ;;
esac

args=()
for f in "${files[@]}"; do args+=(--file "$f"); done

if ! command -v cargo-mutants >/dev/null; then
  echo "cargo-mutants is not installed: cargo install cargo-mutants --locked" >&2
  exit 2
fi

# --list builds nothing: it lists in this checkout and leaves the scratch
# copy alone (refreshing it under a running job would overwrite the mutated
# file of the mutant being tested)
for arg in "$@"; do
  if [ "$arg" = "--list" ]; then
    exec cargo mutants "${args[@]}" "$@"
  fi
done

scratch="${MUTANTS_SCRATCH:-/tmp/pdesculpt-mutants}"
mkdir -p "$scratch/target/debug" mutants.out
# one job at a time on the scratch copy (scripts/nan_inject.sh takes the
# same lock)
exec 9>"$scratch.lock"
if ! flock -n 9; then
  echo "another mutation or NaN-injection job is using $scratch; wait for it" >&2
  exit 2
fi
rm -rf "$scratch/src" && mkdir -p "$scratch/src"
tar -C "$root" --exclude=./target --exclude=./mutants.out --exclude=./.git -cf - . | tar -C "$scratch/src" -xf -
if [ ! -e "$scratch/target/debug/deps" ] && [ -d "$root/target/debug/deps" ]; then
  # deps/ and build/ as hard links (rustc replaces an output by a new
  # file, which breaks the link); .fingerprint/ as a copy: cargo rewrites
  # its files in place, and shared ones made this checkout's cargo take the
  # scratch copy's builds for its own
  for d in deps build; do
    cp -al "$root/target/debug/$d" "$scratch/target/debug/$d"
  done
  cp -a "$root/target/debug/.fingerprint" "$scratch/target/debug/.fingerprint"
fi

export PDESCULPT_MUTANTS_FAMILY="$family"
if [ "$family" = jet ]; then
  # the jets are generic and inlined into every module: at the dev
  # profile's opt-level 1 a mutant rebuilds in about 70 s, at 0 in about
  # 7 s, and the jet checks take well under a second either way
  export CARGO_PROFILE_DEV_OPT_LEVEL=0
fi
export CARGO_TARGET_DIR="$scratch/target"
cd "$scratch/src"

exec nice -n 10 cargo mutants \
  "${args[@]}" \
  --in-place \
  --output "$root/mutants.out/$family" \
  --cargo-arg=--lib \
  "$@" \
  -- -- --include-ignored "${skip[@]}" "$filter" mutants_oracle
