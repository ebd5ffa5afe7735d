#!/usr/bin/env bash
# The six real bodies of docs/drawing-corpus.md (MakeHuman's base body and
# five macro targets): each one's front silhouette and armless side, built
# at the intermediate level, one line each (front and side: largest miss /
# how far the model leaves the outline, % of the height; largest turn;
# creased length / height; the arms' largest turns).
#
#     bash scripts/real_bodies.sh [BIN] [DIR] [more]
#
# BIN: the pdesculpt binary (default target/release/pdesculpt); DIR: where
# the bodies, drawings and models go (default /tmp/real-bodies); `more`:
# also thirty-three macro targets the construction was not developed on
# (docs/drawing-corpus.md, thirty-first measurement). Needs python3, no
# packages.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${1:-target/release/pdesculpt}
dir=${2:-/tmp/real-bodies}
mkdir -p "$dir"
targets=data/makehuman/targets/macrodetails
names="base caucasian-male-young asian-male-old caucasian-female-child
  universal-female-young-averagemuscle-maxweight universal-male-young-maxmuscle-minweight"
if [ "${3:-}" = more ]; then
  names="$names african-female-young asian-female-old caucasian-male-old african-male-child
    universal-female-old-minmuscle-minweight universal-male-old-maxmuscle-maxweight
    universal-female-young-maxmuscle-maxweight universal-male-young-minmuscle-maxweight
    caucasian-female-young asian-male-young african-male-old
    universal-male-child-averagemuscle-maxweight caucasian-female-baby
    african-female-old african-male-young asian-female-young asian-female-child
    caucasian-female-old asian-male-child universal-female-child-minmuscle-maxweight
    universal-female-old-maxmuscle-minweight universal-female-young-minmuscle-minweight
    universal-male-old-minmuscle-minweight universal-male-old-averagemuscle-minweight
    universal-female-young-maxmuscle-minweight universal-male-child-maxmuscle-minweight
    universal-male-young-maxmuscle-averageweight universal-male-old-minmuscle-averageweight
    african-female-child asian-male-baby caucasian-male-child
    universal-female-baby-maxmuscle-maxweight asian-female-baby"
fi
for name in $names; do
  obj=$dir/$name.obj
  if [ "$name" = base ]; then
    cp data/makehuman/base.obj "$obj"
  else
    python3 scripts/morph_obj.py data/makehuman/base.obj "$targets/$name.target.gz" "$obj"
  fi
  python3 scripts/armless_obj.py "$obj" body 1000 0 "$dir/${name}_body.obj" >/dev/null 2>&1
  python3 scripts/armless_obj.py "$obj" body 1.9 0 "$dir/${name}_armless.obj" >/dev/null 2>&1
  "$bin" profile extract "$dir/${name}_body.obj" --view front --input-unit dm -o "$dir/${name}_front.svg" >/dev/null 2>&1
  "$bin" profile extract "$dir/${name}_armless.obj" --view side --input-unit dm -o "$dir/${name}_side.svg" >/dev/null 2>&1
  if ! "$bin" --json sketch build --front "$dir/${name}_front.svg" --side "$dir/${name}_side.svg" \
    --level intermediate -o "$dir/$name.model.obj" 2>"$dir/$name.err" >"$dir/$name.json"; then
    printf '%-48s failed: %s\n' "$name" "$(tail -c 200 "$dir/$name.err")"
    continue
  fi
  python3 - "$name" "$dir/$name.json" <<'PY'
import json, sys
name, path = sys.argv[1:3]
q = json.load(open(path))["quality"]
w = q["whole"]
views = " ".join("%s %.2f/%.2f" % (v["view"], 100 * v["max_rel"], 100 * v["outside_rel"]) for v in w["views"])
arms = " ".join("%.0f" % p["dihedral_deg"] for p in q["parts"] if p["part"].startswith("arm"))
print("%-48s %s turn %.0f creased %.2f arms %s" % (name, views, w["dihedral_deg"], w["creased_rel"], arms))
PY
done
