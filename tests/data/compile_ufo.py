#!/usr/bin/env python3
"""Compile a UFO written by `lncert font` with an independent compiler
(ufo2ft, read with ufoLib2) to a TrueType font, and check with fontTools that
every compiled glyph matches the UFO's outline.

    compile_ufo.py IN.ufo OUT.ttf [LNCERT REPORT.json]

With the lncert binary and the font job's JSON report, every compiled glyph
is also certified against the exact offset: `lncert hausdorff` certifies
d_H(compiled glyph, UFO glyph) ≤ h, and the report's proven bound b is
d_H(UFO glyph, exact offset boundary), so the compiled glyph is within b + h
of it (triangle inequality); h must not exceed the compiler's tolerance.

The compiler converts the cubics to quadratics (cu2qu, at most
`MAX_ERR_EM` em) and rounds the points to integers, so points are not compared;
per glyph, the check is:
  * the same number of contours;
  * the signed area (fontTools AreaPen, exact for quadratics and cubics)
    is the negative of the UFO's (reversed for TrueType) up to perimeter * tol, tol = MAX_ERR_EM * unitsPerEm + 1
    (the conversion error plus the integer rounding);
  * the bounding boxes differ by at most tol on each side;
  * the code points and advance widths are kept.
`lncert font` writes the outlines in the UFO direction (outer contours
counter-clockwise); ufo2ft reverses them for TrueType, as for any UFO.
Exit 0 when every glyph matches, 1 otherwise.
"""
import json
import os
import subprocess
import sys
import tempfile

import ufoLib2
import ufo2ft
from fontTools.pens.areaPen import AreaPen
from fontTools.pens.boundsPen import BoundsPen
from fontTools.pens.perimeterPen import PerimeterPen
from fontTools.ttLib import TTFont

MAX_ERR_EM = 0.001


def measure(draw, glyphset):
    a, b, p = AreaPen(glyphset), BoundsPen(glyphset), PerimeterPen(glyphset)
    for pen in (a, b, p):
        draw(pen)
    return a.value, b.bounds, p.value


def certify_against_exact(name, ufo_glyph, compiled, glyphset, lncert, bound, tol, tmp):
    """Certified d_H(compiled, UFO glyph) by `lncert hausdorff`; returns
    (total bound, problem or None)."""
    from fontTools.pens.svgPathPen import SVGPathPen

    paths = []
    for tag, draw, gs in (("c", compiled.draw, glyphset), ("u", ufo_glyph.draw, None)):
        pen = SVGPathPen(gs)
        draw(pen)
        path = os.path.join(tmp, f"{tag}.svg")
        with open(path, "w") as f:
            f.write(pen.getCommands())
        paths.append(path)
    run = subprocess.run([lncert, "hausdorff", *paths, "--json"], capture_output=True, text=True)
    if run.returncode not in (0, 3) or not run.stdout:
        return float("inf"), f"lncert hausdorff failed: {run.stderr.strip()[:200]}"
    d = json.loads(run.stdout)
    h = d["hi"]
    if d.get("incomplete") or h is None or not h <= tol:
        return float("inf"), f"d_H(compiled, UFO) certified only ≤ {h} (allowed {tol:.2f})"
    return bound + h, None


def main():
    src, dst = sys.argv[1], sys.argv[2]
    lncert = sys.argv[3] if len(sys.argv) > 3 else None
    proven = {}
    if len(sys.argv) > 4:
        with open(sys.argv[4]) as f:
            for g in json.load(f)["glyphs"]:
                if g.get("verdict") == "proven":
                    proven[g["name"]] = g["bound"]
    tmp = tempfile.mkdtemp()
    worst = 0.0
    certified = 0
    ufo = ufoLib2.Font.open(src)
    upm = ufo.info.unitsPerEm
    tol = MAX_ERR_EM * upm + 1.0
    ttf = ufo2ft.compileTTF(
        ufo,
        useProductionNames=False,
        cubicConversionError=MAX_ERR_EM,
    )
    ttf.save(dst)
    ttf = TTFont(dst)
    gs = ttf.getGlyphSet()
    cmap = ttf.getBestCmap()
    hmtx = ttf["hmtx"]
    bad = 0
    for g in ufo:
        name = g.name
        if name not in gs:
            print(f"{name}: missing in the compiled font")
            bad += 1
            continue
        ua, ub, up = measure(g.draw, ufo)
        ta, tb, _ = measure(gs[name].draw, gs)
        problems = []
        nc = len(ttf["glyf"][name].endPtsOfContours) if ttf["glyf"][name].numberOfContours > 0 else 0
        if nc != len(g.contours):
            problems.append(f"{nc} contours compiled, {len(g.contours)} in the UFO")
        # the compiler reverses the contours (TrueType direction): the signed
        # area changes sign
        if abs(ua + ta) > up * tol + 1e-9:
            problems.append(f"area {ta} compiled, {ua} in the UFO (allowed {up * tol:.1f})")
        if (ub is None) != (tb is None) or (
            ub is not None and max(abs(x - y) for x, y in zip(ub, tb)) > tol
        ):
            problems.append(f"bounds {tb} compiled, {ub} in the UFO")
        for cp in g.unicodes:
            if cmap.get(cp) != name:
                problems.append(f"U+{cp:04X} maps to {cmap.get(cp)}")
        if hmtx[name][0] != round(g.width):
            problems.append(f"advance {hmtx[name][0]} compiled, {g.width} in the UFO")
        if lncert and name in proven and not problems:
            total, problem = certify_against_exact(
                name, g, gs[name], gs, lncert, proven[name], tol, tmp
            )
            if problem:
                problems.append(problem)
            else:
                certified += 1
                worst = max(worst, total)
        if problems:
            bad += 1
            print(f"{name}: " + "; ".join(problems))
    n = len(ufo)
    print(f"compile_ufo: {n} glyphs compiled to {dst}; {n - bad} match the UFO within {tol:.2f} font units")
    if lncert:
        print(
            f"compile_ufo: {certified} compiled glyphs certified within {worst:.3f} font units of the exact offset "
            f"(the proven bound plus the certified d_H(compiled, UFO))"
        )
        if certified != len(proven):
            bad += 1
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
