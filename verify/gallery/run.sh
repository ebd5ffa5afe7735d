#!/usr/bin/env bash
# The gallery browser test (verify/gallery/test.mjs) with what it needs:
# Debian's chromium (installed with apt-get when missing) and, from the npm
# registry into a scratch directory, playwright-core and three. Skips with a
# notice only when Chromium cannot be installed; any other failure fails.
# Usage: verify/gallery/run.sh [OUT_DIR]   (default paper_figures/out)
set -euo pipefail
cd "$(dirname "$0")/../.."
out="${1:-paper_figures/out}"
chromium="${CHROMIUM:-/usr/bin/chromium}"
if [ ! -x "$chromium" ] && command -v apt-get >/dev/null 2>&1; then
  { apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium; } >/dev/null 2>&1 || true
fi
if [ ! -x "$chromium" ]; then
  echo "notice: Chromium could not be installed; gallery browser test skipped"
  exit 0
fi
dir="${TMPDIR:-/tmp}/pdesculpt-gallery-test"
npm install --silent --no-audit --no-fund --prefix "$dir" playwright-core@1.64.1 three@0.170.0 >/dev/null
GALLERY_NODE_MODULES="$dir/node_modules" CHROMIUM="$chromium" node verify/gallery/test.mjs "$out"
# The README shows verify/gallery/screenshot.png: every passing run replaces
# it with the screenshot it just took, so the committed picture is the page
# as the last test run saw it (commit it with the change that altered the page).
cp "$out/gallery-screenshot.png" verify/gallery/screenshot.png
echo "updated verify/gallery/screenshot.png"
