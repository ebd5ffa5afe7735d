#!/usr/bin/env python3
"""Bad-input probe of the release binary for issue 35 (drawings, documents,
edits, saves). Each probe runs alone in a fresh scratch directory under
`timeout` and an address-space cap (`prlimit --as`), so no probe can take a
shared machine down.

Usage: scripts/probe_hardening.py [--bin target/release/pdesculpt]
       [--timeout 20] [--mem-gib 4] [--only SUBSTRING] [--keep]

Prints one line per probe: verdict, exit code, wall seconds, the first line
of stderr. Verdicts: ok (a clear error, or exit 0 where success is right),
PANIC (exit 101 / "panicked"), HANG (timeout), ABORT (killed, allocation
failure), NAN0 (exit 0 with NaN/inf printed), WROTE (a file the probe says
must not change or appear did), READ (strace saw a file opened that the
command did not name), LOST (an edit missing after concurrent edits).
Exits 1 when any probe is not ok.
"""

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import threading
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = os.path.join(ROOT, "data", "sketch")

OK_SVG = open(os.path.join(DATA, "male_front.svg")).read()


def svg(body, attrs=""):
    return f'<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" {attrs}>{body}</svg>'


BLOB = svg('<path id="o" d="M 0 0 C 0.3 -0.5 0.7 -0.5 1 0 C 0.7 0.5 0.3 0.5 0 0 Z"/>')


def cubic(size):
    s = size
    return svg(f'<path id="o" d="M 0 0 C {s} 0 {s} {s} 0 {s} Z"/>')


def arc(r):
    return svg(f'<path id="o" d="M 0 0 A {r} {r} 0 1 1 1 0 Z"/>')


class Ctx:
    def __init__(self, d, bin_, timeout, mem):
        self.d, self.bin, self.timeout, self.mem = d, bin_, timeout, mem

    def path(self, name):
        return os.path.join(self.d, name)

    def write(self, name, text):
        p = self.path(name)
        with open(p, "w") as f:
            f.write(text)
        return p

    def run(self, args, strace=False):
        cmd = ["prlimit", f"--as={self.mem}", "timeout", "-s", "KILL", str(self.timeout)]
        if strace:
            cmd += ["strace", "-f", "-qq", "-e", "trace=openat,open", "-o", self.path("strace.log")]
        cmd += [self.bin] + args
        t = time.time()
        p = subprocess.run(cmd, cwd=self.d, capture_output=True, text=True, errors="replace")
        return p.returncode, time.time() - t, p.stdout, p.stderr

    def base_doc(self):
        """A built male document in the scratch directory: doc.json."""
        rc, _, _, err = self.run(
            ["sketch", "build", "--front", os.path.join(DATA, "male_front.svg"), "--side",
             os.path.join(DATA, "male_side.svg"), "-o", "base.obj", "--save-doc", "doc.json"])
        if rc != 0:
            raise RuntimeError("base document: " + err)
        os.remove(self.path("base.obj"))
        return self.path("doc.json")

    def doc_edit(self, fn):
        p = self.base_doc()
        d = json.load(open(p))
        fn(d)
        json.dump(d, open(p, "w"))
        return p


def classify(rc, out, err):
    text = out + err
    if rc == 101 or "panicked" in text:
        return "PANIC"
    if rc in (124, 137, -9) or rc < 0:
        return "HANG" if rc in (124, 137, -9) else "ABORT"
    if rc == 134 or "memory allocation" in text:
        return "ABORT"
    if rc == 0 and any(w in text for w in ("NaN", " inf", "null")):
        return "NAN0"
    return "ok"


PROBES = []


def probe(name, expect="error"):
    def deco(f):
        PROBES.append((name, expect, f))
        return f
    return deco


# ---- drawings ---------------------------------------------------------------

@probe("profile check tolerance 1e-300")
def _(c):
    return c.run(["profile", "check", c.write("b.svg", BLOB), "--view", "front", "--tolerance", "1e-300"])


for size in ["1e30", "1e12", "1e11"]:
    @probe(f"sketch build cubic {size}")
    def _(c, size=size):
        return c.run(["sketch", "build", "--front", c.write("c.svg", cubic(size)), "-o", "o.obj"])

    @probe(f"profile check cubic {size}")
    def _(c, size=size):
        return c.run(["profile", "check", c.write("c.svg", cubic(size)), "--view", "front"])


@probe("sketch build arc r 1e30")
def _(c):
    return c.run(["sketch", "build", "--front", c.write("a.svg", arc("1e30")), "-o", "o.obj"])


@probe("profile check 400 circles r 1e9")
def _(c):
    body = "".join(f'<circle cx="{i}" cy="0" r="1e9"/>' for i in range(400))
    return c.run(["profile", "check", c.write("m.svg", svg(body)), "--view", "front"])


def image_svg(href):
    return svg(f'<image xlink:href="{href}" width="1" height="1"/>' + OK_SVG.split(">", 1)[1].rsplit("</svg>", 1)[0])


@probe("image href /etc/passwd (strace)")
def _(c):
    r = c.run(["profile", "check", c.write("i.svg", image_svg("/etc/passwd")), "--view", "front"], strace=True)
    log = open(c.path("strace.log")).read()
    if "/etc/passwd" in log:
        return r[0], r[1], r[2], "READ /etc/passwd: " + r[3]
    return r


for cmd in ["sketch", "profile", "character"]:
    @probe(f"image href FIFO ({cmd})")
    def _(c, cmd=cmd):
        os.mkfifo(c.path("fifo"))
        p = c.write("i.svg", image_svg(c.path("fifo")))
        if cmd == "sketch":
            return c.run(["sketch", "build", "--front", p, "-o", "o.obj"])
        if cmd == "profile":
            return c.run(["profile", "check", p, "--view", "front"])
        d = c.base_doc()
        j = json.load(open(d))
        j["inputs"]["front"] = {"path": "i.svg"}
        j["inputs"]["side"] = None
        j["level"] = "initial"
        j["parts"], j["transitions"] = [], []
        json.dump(j, open(d, "w"))
        return c.run(["character", "build", d, "-o", "o.obj"])


@probe("image href /dev/zero")
def _(c):
    return c.run(["sketch", "build", "--front", c.write("i.svg", image_svg("/dev/zero")), "-o", "o.obj"])


@probe("document front path is a FIFO")
def _(c):
    os.mkfifo(c.path("fifo.svg"))
    d = c.doc_edit(lambda j: j["inputs"].update(front={"path": "fifo.svg"}))
    return c.run(["character", "build", d, "-o", "o.obj"])


@probe("document front path is /dev/zero")
def _(c):
    d = c.doc_edit(lambda j: j["inputs"].update(front={"path": "/dev/zero"}))
    return c.run(["character", "build", d, "-o", "o.obj"])


@probe("document front path is a directory")
def _(c):
    os.mkdir(c.path("dir.svg"))
    d = c.doc_edit(lambda j: j["inputs"].update(front={"path": "dir.svg"}))
    return c.run(["character", "build", d, "-o", "o.obj"])


@probe("side view 5 m above the front")
def _(c):
    side = open(os.path.join(DATA, "male_side.svg")).read()
    side = side.replace('<path', '<g transform="translate(0,-5)"><path', 1).replace("</svg>", "</g></svg>")
    return c.run(["sketch", "build", "--front", os.path.join(DATA, "male_front.svg"), "--side",
                  c.write("s.svg", side), "-o", "o.obj"])


@probe("scale(NaN) transform")
def _(c):
    s = OK_SVG.replace('<path', '<g transform="scale(NaN)"><path', 1).replace("</svg>", "</g></svg>")
    return c.run(["profile", "check", c.write("n.svg", s), "--view", "front"])


@probe("closed path with id cut_x")
def _(c):
    s = OK_SVG.replace("</svg>", '<path id="cut_x" d="M -0.3 -1 L 0.3 -1 L 0 -1.2 Z"/></svg>')
    return c.run(["sketch", "build", "--front", c.write("x.svg", s), "-o", "o.obj"])


@probe("NaN in path data")
def _(c):
    return c.run(["profile", "check", c.write("n.svg", svg('<path id="o" d="M 0 0 L NaN 1 L 1 1 Z"/>')), "--view", "front"])


@probe("f32 overflow in path data")
def _(c):
    return c.run(["profile", "check", c.write("n.svg", svg('<path id="o" d="M 0 0 L 1e39 1 L 1 1 Z"/>')), "--view", "front"])


@probe("1e30-sized drawing")
def _(c):
    s = svg('<path id="o" d="M 0 0 L 1e30 0 L 1e30 -2e30 L 0 -2e30 Z"/>')
    return c.run(["sketch", "build", "--front", c.write("h.svg", s), "-o", "o.obj"])


@probe("UTF-8 BOM document")
def _(c):
    d = c.base_doc()
    t = open(d, encoding="utf-8").read()
    open(d, "w", encoding="utf-8").write("\ufeff" + t)
    return c.run(["character", "build", d, "-o", "o.obj"])


@probe("profile extract of a 1e39 cube then check")
def _(c):
    v = [(x, y, z) for x in (0, 1e37) for y in (0, 1e37) for z in (0, 1e37)]
    obj = "".join(f"v {x} {y} {z}\n" for x, y, z in v)
    obj += "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n"
    c.write("cube.obj", obj)
    rc, t, out, err = c.run(["profile", "extract", "cube.obj", "--view", "front", "-o", "cube.svg"])
    if rc == 0:
        rc2, _, out2, err2 = c.run(["profile", "check", "cube.svg", "--view", "front"])
        if rc2 != 0:
            return 0, t, out, "NAN0-like: extract wrote an SVG its check rejects: " + err2
    return rc, t, out, err


# ---- documents --------------------------------------------------------------

def part_sections(j, part, n):
    p = next(p for p in j["parts"] if p["name"] == part)
    s = p["sections"]
    u1 = s[-1]["u"]
    c0, c1 = s[0]["centre"], s[-1]["centre"]
    out = []
    for k in range(n):
        t = k / (n - 1)
        q = dict(s[0])
        q["u"] = t * u1
        q["centre"] = [a + t * (b - a) for a, b in zip(c0, c1)]
        q["shape"] = {"circle": {"r": 0.05}}
        out.append(q)
    p["sections"] = out


for n in [100000, 1000]:
    @probe(f"part with {n} sections")
    def _(c, n=n):
        d = c.doc_edit(lambda j: part_sections(j, "head", n))
        return c.run(["character", "build", d, "-o", "o.obj"])


@probe("GEC with 5000 harmonics")
def _(c):
    def f(j):
        s = j["parts"][1]["sections"][5]
        s["shape"] = {"gec": {"centre": [0, 0], "x": [[0.05, 0]] + [[0, 0]] * 4999, "y": [[0, 0.05]] + [[0, 0]] * 4999}}
    return c.run(["character", "build", c.doc_edit(f), "-o", "o.obj"])


@probe("key section of 200k points")
def _(c):
    import math
    pts = [[0.1 * math.cos(2 * math.pi * k / 200000), 0.1 * math.sin(2 * math.pi * k / 200000)] for k in range(200000)]
    def f(j):
        j["level"] = "final"
        j["parts"], j["transitions"] = [], []
        j["inputs"]["sections"] = [{"part": "torso", "y": 1.2, "points": pts}]
    return c.run(["character", "build", c.doc_edit(f), "-o", "o.obj"])


@probe("100k-edit log")
def _(c):
    e = {"op": "shape_parameter", "part": "torso", "a": 0.3}
    d = c.doc_edit(lambda j: j.update(edits=[e] * 100000, cursor=100000))
    return c.run(["character", "build", d, "-o", "o.obj"])


@probe("conv stroke.spacing 1.0001e-4 prop")
def _(c):
    m = json.load(open(os.path.join(ROOT, "data", "conv", "blob.json")))
    m.setdefault("options", {}).setdefault("stroke", {})["spacing"] = 1.0001e-4
    json.dump(m, open(c.path("prop.json"), "w"))
    d = c.doc_edit(lambda j: j.update(props=[{"name": "p", "model": "prop.json"}]))
    return c.run(["character", "build", d, "-o", "o.obj"])


def setshape(part, k, shape):
    def f(j):
        next(p for p in j["parts"] if p["name"] == part)["sections"][k]["shape"] = shape
    return f


for name, fn in [
    ("section radius 1e30", setshape("arm_l", 5, {"circle": {"r": 1e30}})),
    ("ellipse a = b = 0", setshape("arm_l", 5, {"ellipse": {"a": 0, "b": 0, "offset": 0}})),
    ("frame e1 = 0", lambda j: j["parts"][2]["sections"][5].update(e1=[0, 0, 0])),
    ("frame e1 = e2", lambda j: j["parts"][2]["sections"][5].update(e1=j["parts"][2]["sections"][5]["e2"])),
    ("removed part named torso", lambda j: j.update(removed_parts=[{"name": "torso", "front": {"path": os.path.join(DATA, "male_front.svg")}}])),
    ("section value 1e308", lambda j: j["parts"][2]["sections"][5].update(centre=[1e308, 0, 0])),
]:
    @probe(f"document {name}")
    def _(c, fn=fn):
        return c.run(["character", "build", c.doc_edit(fn), "-o", "o.obj"])


# ---- edits ------------------------------------------------------------------

EDITS = {
    "force p 1e30": {"op": "force", "part": "arm_l", "u": [0.1, 0.4], "force": {"type": "uniform", "p": [1e30, 0, 0]}},
    "boundary tangent 1e30": {"op": "boundary", "part": "arm_l", "end": "end", "tangent": [1e30, 0, 0]},
    "plate d 1e30": {"op": "plate", "part": "torso", "centre": [0.0, 1.1, 0.1], "radius": 0.05, "d": [0, 0, 1e30]},
    "gec translate 1e308": {"op": "gec_transform", "part": "arm_l", "transform": {"kind": "translate", "d": [1e308, 0, 0]}},
}

for name, e in EDITS.items():
    @probe(f"edit {name}, then build")
    def _(c, e=e):
        d = c.base_doc()
        before = open(d).read()
        rc, t, out, err = c.run(["character", "edit", d, "--op", c.write("op.json", json.dumps(e))])
        if rc == 0:
            rc2, _, out2, err2 = c.run(["character", "build", d, "-o", "o.obj"])
            if rc2 != 0 or classify(rc2, out2, err2) != "ok":
                return 0, t, out + out2, "NAN0-like: edit accepted, then build: " + err2
            return rc2, t, out2, err2
        if open(d).read() != before:
            return rc, t, out, "WROTE doc changed by a refused edit: " + err
        return rc, t, out, err


@probe("redo of an unbuildable edit")
def _(c):
    e = EDITS["gec translate 1e308"]
    def f(j):
        j["edits"] = [e]
        j["cursor"] = 0
    d = c.doc_edit(f)
    rc, t, out, err = c.run(["character", "redo", d])
    if rc == 0:
        return 0, t, out, "NAN0-like: redo accepted an unbuildable edit"
    return rc, t, out, err


@probe("two concurrent character edit runs", expect="lost")
def _(c):
    d = c.base_doc()
    lost = 0
    trials = 5
    for k in range(trials):
        j = json.load(open(d))
        j["edits"], j["cursor"] = [], 0
        json.dump(j, open(d, "w"))
        a = c.write("a.json", json.dumps({"op": "shape_parameter", "part": "torso", "a": 0.3}))
        b = c.write("b.json", json.dumps({"op": "shape_parameter", "part": "head", "a": 0.2}))
        procs = [subprocess.Popen([c.bin, "character", "edit", d, "--op", x], cwd=c.d,
                                  stdout=subprocess.PIPE, stderr=subprocess.PIPE) for x in (a, b)]
        codes = [p.wait(timeout=c.timeout * 3) for p in procs]
        n = len(json.load(open(d))["edits"])
        if n < sum(1 for x in codes if x == 0):
            lost += 1
    if lost:
        return 0, 0.0, "", f"LOST an edit in {lost} of {trials} trials"
    return 0, 0.0, "", f"no lost edit in {trials} trials"


# ---- files ------------------------------------------------------------------

@probe("edit through a symlink")
def _(c):
    d = c.base_doc()
    os.rename(d, c.path("real.json"))
    os.symlink("real.json", d)
    rc, t, out, err = c.run(["character", "edit", d, "--op", c.write("op.json", json.dumps({"op": "shape_parameter", "part": "torso", "a": 0.3}))])
    if not os.path.islink(d):
        return rc, t, out, "WROTE the symlink replaced by a file: " + err
    if len(json.load(open(c.path("real.json")))["edits"]) != 1:
        return rc, t, out, "WROTE the target did not get the edit: " + err
    return rc, t, out, err


@probe("edit keeps mode 600")
def _(c):
    d = c.base_doc()
    os.chmod(d, 0o600)
    rc, t, out, err = c.run(["character", "edit", d, "--op", c.write("op.json", json.dumps({"op": "shape_parameter", "part": "torso", "a": 0.3}))])
    mode = os.stat(d).st_mode & 0o777
    if mode != 0o600:
        return rc, t, out, f"WROTE mode became {oct(mode)}: " + err
    return rc, t, out, err


def unchanged(c, files, args):
    before = {f: open(c.path(f), "rb").read() for f in files}
    rc, t, out, err = c.run(args)
    for f in files:
        if open(c.path(f), "rb").read() != before[f]:
            return rc, t, out, f"WROTE {f} overwritten: " + err
    return rc, t, out, err


@probe("sketch build --save-doc equal to --front")
def _(c):
    shutil.copy(os.path.join(DATA, "male_front.svg"), c.path("F.svg"))
    return unchanged(c, ["F.svg"], ["sketch", "build", "--front", "F.svg", "-o", "o.obj", "--save-doc", "F.svg"])


@probe("sketch build --save-doc equal to --sections")
def _(c):
    shutil.copy(os.path.join(DATA, "male_sections.json"), c.path("S.json"))
    return unchanged(c, ["S.json"], ["sketch", "build", "--front", os.path.join(DATA, "male_front.svg"), "--side",
                                     os.path.join(DATA, "male_side.svg"), "--sections", "S.json", "-o", "o.obj", "--save-doc", "S.json"])


@probe("template fit -o equal to --template")
def _(c):
    c.write("T.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n")
    return unchanged(c, ["T.obj"], ["template", "fit", "--template", "T.obj", "--front", os.path.join(DATA, "male_front.svg"), "-o", "T.obj"])


@probe("--save-doc equal to -o")
def _(c):
    rc, t, out, err = c.run(["sketch", "build", "--front", os.path.join(DATA, "male_front.svg"), "-o", "x.obj", "--save-doc", "x.obj"])
    if os.path.exists(c.path("x.obj")):
        return rc, t, out, "WROTE x.obj: " + err
    return rc, t, out, err


@probe("-o that cannot be written, with --save-doc")
def _(c):
    # a missing directory is created (as every writer does); a directory
    # that cannot be created (under a regular file) must fail before
    # --save-doc is written
    c.write("file.txt", "x")
    rc, t, out, err = c.run(["sketch", "build", "--front", os.path.join(DATA, "male_front.svg"), "-o", "file.txt/x.obj", "--save-doc", "d.json"])
    if os.path.exists(c.path("d.json")):
        return rc, t, out, "WROTE d.json before failing: " + err
    return rc, t, out, err


@probe("tbsm replace -o x.obj")
def _(c):
    d = c.base_doc()
    rc, t, out, err = c.run(["template", "tbsm", "replace", d, "--part", "leg_l", "-o", "x.obj"])
    if os.path.exists(c.path("x.obj")):
        return rc, t, out, "WROTE JSON into x.obj: " + err
    return rc, t, out, err


@probe("tui on /nonexistent/dir/x.json creates nothing")
def _(c):
    target = c.path("nodir/sub/x.json")
    sess = f"probe{os.getpid()}"
    subprocess.run(["tmux", "new-session", "-d", "-s", sess, "-x", "120", "-y", "40",
                    f"timeout -s KILL {c.timeout} {c.bin} tui {target}"], cwd=c.d)
    time.sleep(4)
    for keys in (["Escape"], ["q"], ["n"], ["q"]):
        subprocess.run(["tmux", "send-keys", "-t", sess] + keys)
        time.sleep(0.5)
    time.sleep(1)
    subprocess.run(["tmux", "kill-session", "-t", sess], capture_output=True)
    if os.path.exists(c.path("nodir")):
        return 0, 0.0, "", "WROTE the TUI created " + ", ".join(
            os.path.join(r, f) for r, ds, fs in os.walk(c.path("nodir")) for f in ds + fs)
    return 0, 0.0, "", "nothing created"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", default=os.path.join(ROOT, "target", "release", "pdesculpt"))
    ap.add_argument("--timeout", type=int, default=20)
    ap.add_argument("--mem-gib", type=int, default=4)
    ap.add_argument("--only", default="")
    ap.add_argument("--keep", action="store_true")
    a = ap.parse_args()
    bad = 0
    for name, expect, f in PROBES:
        if a.only and a.only not in name:
            continue
        d = tempfile.mkdtemp(prefix="pdesculpt-probe-")
        c = Ctx(d, os.path.abspath(a.bin), a.timeout, a.mem_gib << 30)
        try:
            rc, t, out, err = f(c)
        except Exception as e:  # a probe that could not run is a failure too
            rc, t, out, err = -1, 0.0, "", f"probe error: {e}"
        v = classify(rc, out, err)
        first = (err.strip().splitlines() or [""])[-1]
        for tag in ("READ", "WROTE", "LOST", "NAN0-like"):
            if err.startswith(tag):
                v = tag.split("-")[0]
                first = err.splitlines()[0]
        if v != "ok":
            bad += 1
        print(f"{v:5} rc={rc:<4} {t:6.1f}s  {name}: {first[:300]}", flush=True)
        if not a.keep:
            shutil.rmtree(d, ignore_errors=True)
    print(f"\n{bad} probes not ok")
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
