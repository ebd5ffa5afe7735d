#!/usr/bin/env bash
# A PNG of `pdesculpt tui` as a terminal shows it (the README's screenshot).
#
# Runs the TUI in a detached tmux session on the bundled female, waits for the
# first build, selects a part (arm_l), applies one GEC scale edit, attaches a
# prop (data/conv/blob.json) and shows the three views; captures the pane with its colours (`tmux capture-pane
# -e`), turns the ANSI text into HTML (python3, below) and screenshots that
# with headless Chromium (Debian `chromium`, as the gallery test uses).
#
#   scripts/tui-screenshot.sh [OUT.png]      (default docs/tui.png)
#
# Needs tmux, python3, chromium and a release build (target/release/pdesculpt
# or $PDESCULPT).
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-docs/tui.png}"
bin="${PDESCULPT:-${CARGO_TARGET_DIR:-target}/release/pdesculpt}"
chromium="${CHROMIUM:-/usr/bin/chromium}"
cols=170
rows=46
for t in tmux python3 "$chromium" "$bin"; do
  command -v "$t" >/dev/null 2>&1 || { echo "error: $t not found" >&2; exit 1; }
done
tmp="$(mktemp -d)"
session="pdesculpt-shot-$$"
cleanup() { tmux kill-session -t "$session" 2>/dev/null || true; rm -rf "$tmp"; }
trap cleanup EXIT
TERM=xterm-256color tmux new-session -d -s "$session" -x "$cols" -y "$rows" \
  "exec $bin tui $tmp/char.json --bundled female"
wait_for() {
  for _ in $(seq 1 900); do
    s="$(tmux capture-pane -p -t "$session")"
    if grep -q -- "$1" <<<"$s" && ! grep -q -- "rebuilding" <<<"$s"; then return 0; fi
    sleep 0.2
  done
  echo "error: timed out waiting for '$1'" >&2
  tmux capture-pane -p -t "$session" >&2
  exit 1
}
keys() { for k in "$@"; do tmux send-keys -t "$session" "$k"; sleep 0.1; done; }
wait_for "rebuilt"
# arm_l (third part), its parameters, the scale row, one edit
keys j j Tab j j j Enter
tmux send-keys -t "$session" -l "1.3 1.2"
keys Enter
wait_for "1 of 1 active"
# a prop from a conv model beside the body (issue 14's prop command)
keys p
tmux send-keys -t "$session" -l "data/conv/blob.json ball 0.07 0.42 1.05 0"
keys Enter
wait_for "attached prop"
keys v v v
wait_for "front | side | top"
# type a bad value so the screenshot shows the check as typed
keys Up Up Enter
tmux send-keys -t "$session" -l -- "-2"
sleep 0.5
tmux capture-pane -e -p -t "$session" >"$tmp/screen.ansi"
python3 - "$tmp/screen.ansi" "$tmp/screen.html" <<'PY'
import html, re, sys
text = open(sys.argv[1], encoding="utf-8").read().rstrip("\n").split("\n")
base = ["#000000", "#cd3131", "#0dbc79", "#e5e510", "#2472c8", "#bc3fbc", "#11a8cd", "#e5e5e5",
        "#666666", "#f14c4c", "#23d18b", "#f5f543", "#3b8eea", "#d670d6", "#29b8db", "#ffffff"]
def c256(n):
    if n < 16: return base[n]
    if n < 232:
        n -= 16; v = [0, 95, 135, 175, 215, 255]
        return "#%02x%02x%02x" % (v[n // 36], v[(n // 6) % 6], v[n % 6])
    g = 8 + 10 * (n - 232); return "#%02x%02x%02x" % (g, g, g)
FG, BG = "#d0d0d0", "#101218"
out = []
for line in text:
    fg, bg, bold, strike = None, None, False, False
    spans = []
    for part in re.split(r"(\x1b\[[0-9;]*m)", line):
        m = re.fullmatch(r"\x1b\[([0-9;]*)m", part)
        if m:
            codes = [int(c) if c else 0 for c in m.group(1).split(";")]
            i = 0
            while i < len(codes):
                c = codes[i]
                if c == 0: fg, bg, bold, strike = None, None, False, False
                elif c == 1: bold = True
                elif c == 22: bold = False
                elif c == 9: strike = True
                elif c == 29: strike = False
                elif 30 <= c <= 37: fg = base[c - 30]
                elif 90 <= c <= 97: fg = base[c - 90 + 8]
                elif 40 <= c <= 47: bg = base[c - 40]
                elif 100 <= c <= 107: bg = base[c - 100 + 8]
                elif c == 39: fg = None
                elif c == 49: bg = None
                elif c in (38, 48) and i + 1 < len(codes):
                    if codes[i + 1] == 2 and i + 4 < len(codes):
                        col = "#%02x%02x%02x" % tuple(codes[i + 2:i + 5]); i += 4
                    elif codes[i + 1] == 5 and i + 2 < len(codes):
                        col = c256(codes[i + 2]); i += 2
                    else:
                        col = None
                    if c == 38: fg = col
                    else: bg = col
                i += 1
        elif part:
            style = "color:%s;background:%s;%s%s" % (fg or FG, bg or BG,
                "font-weight:bold;" if bold else "", "text-decoration:line-through;" if strike else "")
            # half blocks as two-colour cells (a glyph leaves gaps between lines)
            for run in re.split("(\u2580+)", part):
                if not run:
                    continue
                if run[0] == "\u2580":
                    cell = '<span class="h" style="background:linear-gradient(%s 50%%,%s 50%%)"> </span>' % (
                        fg or FG, bg or BG)
                    spans.append(cell * len(run))
                else:
                    spans.append('<span style="%s">%s</span>' % (style, html.escape(run)))
    out.append("".join(spans))
page = """<!doctype html><meta charset="utf-8"><style>
body{margin:0;background:%s}
pre{margin:8px;font:14px/17px 'DejaVu Sans Mono',monospace;color:%s;letter-spacing:0}
span{display:inline-block;height:17px;vertical-align:top;white-space:pre}
span.h{width:1ch}
</style><pre>%s</pre>""" % (BG, FG, "\n".join(out))
open(sys.argv[2], "w", encoding="utf-8").write(page)
PY
mkdir -p "$(dirname "$out")"
w=$(( cols * 85 / 10 + 16 ))
h=$(( rows * 17 + 16 ))
"$chromium" --headless --no-sandbox --disable-gpu --hide-scrollbars \
  --window-size="$w,$h" --screenshot="$tmp/shot.png" "file://$tmp/screen.html" >/dev/null 2>&1
mv "$tmp/shot.png" "$out"
echo "wrote $out (${w}x${h})"
