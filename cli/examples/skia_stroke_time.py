#!/usr/bin/env python3
"""Skia's stroke + simplify timed on given paths (skia-pathops), for
`cli/examples/icon_strokes.rs`.

Reads one JSON object on stdin:

    {"width": 2.0, "tol": 0.01, "min_batch_seconds": 0.02, "batches": 7,
     "paths": [{"name": "circle",
                "cmds": [["M", x, y], ["L", x, y], ["Q", x1, y1, x, y],
                         ["C", x1, y1, x2, y2, x, y], ["Z"]]}]}

and writes one JSON object on stdout:

    {"pathops": "0.9.2", "python": "3.11.7", "scale": 25.0,
     "results": [{"name": ..., "us": ..., "us_default_res": ...,
                  "overhead_us": ..., "calls": ..., "verbs_out": ...,
                  "verbs_out_default_res": ...}]}

One call is `q = Path(p); q.stroke(width, ROUND_CAP, ROUND_JOIN, 4);
q.simplify(fix_winding=False, keep_starting_points=False)` — Skia's stroker
(`SkStroke` through `skpathutils::FillPathWithPaint`) followed by Skia's
`Simplify` (PathOps), both in C++. `fix_winding` and `keep_starting_points`
are pathops' Python-level post-passes (and `fix_winding` does not accept the
conics of Skia's round joins), so they are off.

Tolerance: pathops strokes with resScale 1, and Skia's stroker then works to
an error term of 1 / (4 · resScale) = 0.25 units (`SkPathStroker`:
`fInvResScale = 1 / (resScale * 4)`). `us` strokes the path scaled by
s = 0.25 / tol with width s · width, which is Skia's stroke at resScale s, i.e.
within ~tol in the original units (the comparable setting); `us_default_res`
is the same call on the unscaled path (tolerance ~0.25 units).

Timing: `time.perf_counter` around batches of calls; the batch size is chosen
so that one batch takes at least `min_batch_seconds`; the reported per-call
time is the median over `batches` batches. `overhead_us` is the same
measurement of the `Path(p)` copy alone (part of `us`).
"""

import json
import statistics
import sys
import time

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


def one_call(p, width):
    q = Path(p)
    q.stroke(width, LineCap.ROUND_CAP, LineJoin.ROUND_JOIN, 4.0)
    q.simplify(fix_winding=False, keep_starting_points=False)
    return q


def copy_only(p, width):
    return Path(p)


def per_call(f, p, width, min_batch, batches):
    """Median seconds per call of `f(p, width)`, and the number of calls."""
    n = 1
    while True:
        t0 = time.perf_counter()
        for _ in range(n):
            f(p, width)
        dt = time.perf_counter() - t0
        if dt >= min_batch or n >= 1 << 22:
            break
        n = max(2 * n, int(n * 1.2 * min_batch / max(dt, 1e-9)))
    times = []
    for _ in range(batches):
        t0 = time.perf_counter()
        for _ in range(n):
            f(p, width)
        times.append((time.perf_counter() - t0) / n)
    return statistics.median(times), n * batches


def segments(q):
    return sum(1 for v in q.verbs if v.name not in ("MOVE", "CLOSE"))


def main():
    job = json.load(sys.stdin)
    width = float(job["width"])
    tol = float(job["tol"])
    min_batch = float(job.get("min_batch_seconds", 0.02))
    batches = int(job.get("batches", 7))
    scale = 0.25 / tol
    results = []
    for item in job["paths"]:
        p = build(item["cmds"], scale)
        p1 = build(item["cmds"], 1.0)
        us, calls = per_call(one_call, p, scale * width, min_batch, batches)
        us1, _ = per_call(one_call, p1, width, min_batch, batches)
        ov, _ = per_call(copy_only, p, scale * width, min_batch, batches)
        results.append(
            {
                "name": item["name"],
                "us": us * 1e6,
                "us_default_res": us1 * 1e6,
                "overhead_us": ov * 1e6,
                "calls": calls,
                "verbs_out": segments(one_call(p, scale * width)),
                "verbs_out_default_res": segments(one_call(p1, width)),
            }
        )
    json.dump(
        {
            "pathops": getattr(pathops, "__version__", "?"),
            "python": sys.version.split()[0],
            "scale": scale,
            "results": results,
        },
        sys.stdout,
    )
    sys.stdout.write("\n")


if __name__ == "__main__":
    main()
