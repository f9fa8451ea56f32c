#!/usr/bin/env python3
"""Skia's stroke outlines (skia-pathops) written as SVG path data, for
`cli/examples/audit_strokers.rs`, which certifies them against the exact
stroke boundary. The output is committed (`cli/examples/data/skia_strokes.json`)
so that the Rust build and the audit do not need Python.

    cargo run --release --example audit_strokers -- --skia-job > job.json
    python3 cli/examples/skia_stroke_dump.py < job.json > cli/examples/data/skia_strokes.json

Input: {"paths": [{"name": ..., "width": w, "tol": t,
                    "cmds": [["M", x, y], ["L", x, y], ["Q", ...], ["C", ...], ["Z"]]}]}
Output: {"pathops": "0.9.2", "outlines": {name: "M x y L ... Z", ...}}

Per path: scaled by s = 0.25 / tol (Skia's stroker works to 1 / (4 resScale)
units and pathops strokes at resScale 1, so this is Skia's stroke at the
tolerance tol), `stroke(s·w, ROUND_CAP, ROUND_JOIN, 4)`, `simplify` (the
boundary of the filled region, Skia's PathOps), conics converted to quadratics
(`convertConicsToQuads`, at Skia's default 0.25 of the scaled units, i.e.
tol in the original units, as Skia's own SVG writer must), scaled back by
1 / s, written with Python's shortest round-trip float repr.
"""

import json
import sys

import pathops
from pathops import LineCap, LineJoin, Path


def build(cmds, s):
    p = Path()
    for c in cmds:
        v, a = c[0], [s * float(x) for x in c[1:]]
        if v == "M":
            p.moveTo(*a)
        elif v == "L":
            p.lineTo(*a)
        elif v == "Q":
            p.quadTo(*a)
        elif v == "C":
            p.cubicTo(*a)
        elif v == "Z":
            p.close()
        else:
            raise ValueError(f"unknown command {v!r}")
    return p


def path_data(p, s):
    # Skia's raw verbs: 0 move, 1 line, 2 quad, 3 conic, 4 cubic, 5 close
    letters = {0: "M", 1: "L", 2: "Q", 4: "C"}
    out = []
    for verb, pts in p:
        verb = int(verb)
        if verb == 5:
            out.append("Z")
        elif verb in letters:
            xy = " ".join(f"{x / s!r} {y / s!r}" for (x, y) in pts)
            out.append(f"{letters[verb]} {xy}")
        else:
            raise ValueError(f"verb {verb} left after convertConicsToQuads")
    return " ".join(out)


def main():
    job = json.load(sys.stdin)
    outlines = {}
    for item in job["paths"]:
        s = 0.25 / float(item["tol"])
        q = build(item["cmds"], s)
        q.stroke(s * float(item["width"]), LineCap.ROUND_CAP, LineJoin.ROUND_JOIN, 4.0)
        q.simplify(fix_winding=False, keep_starting_points=False)
        q.convertConicsToQuads()
        outlines[item["name"]] = path_data(q, s)
    json.dump({"pathops": pathops.__version__, "outlines": outlines}, sys.stdout, indent=1)
    sys.stdout.write("\n")


if __name__ == "__main__":
    main()
