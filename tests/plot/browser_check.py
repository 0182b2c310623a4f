#!/usr/bin/env python3
"""Toolpath pictures as a browser shows them: `tape plot` of a known program (a 100 x 50 mm square fed at
one depth, then a clockwise half circle) to SVG and to an HTML page, opened in headless Chromium and
screenshot; the pixels looked at on the square's sides and on the half circle's low point (G02 from
above: clockwise, under its chord) in the first tool's colour, and at the half circle's high point and
inside the square in the paper's. The page must load with no console message and name each block on
hover (an SVG <title> per stroke). The page's data-x0, data-y0 and data-scale say where the part is.

Usage: browser_check.py TAPE_BINARY. Exit 0 passed, 1 failed, 77 skipped (Chromium missing or unable to
start, or the build has no plot module: the reason is printed).
"""
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "render"))
from browser_check import SKIP, console_messages, find_chromium, read_png, screenshot  # noqa: E402

PROGRAM = """%
O0001
N10 G90 G17 G21 G54 G00 X0 Y0 Z5.
N20 T1 M06
N30 G01 Z-1. F100.
N40 G01 X100.
N50 Y50.
N60 X0
N70 Y0
N80 G00 Z5.
N90 X70. Y25.
N100 G01 Z-1.
N110 G02 X30. Y25. I-20. J0
N120 G00 Z5.
N130 M30
%
"""
TOOL = (0x1F, 0x5F, 0xBF)  # the first tool's colour
WIDTH, HEIGHT = 600, 400


def main():
    tape = os.path.realpath(sys.argv[1])
    chromium = find_chromium()
    if not chromium:
        print("SKIP: no chromium on PATH (scripts/install-deps.sh installs it)")
        return SKIP
    failures = []
    with tempfile.TemporaryDirectory(prefix="tape-plot-") as work:
        src = os.path.join(work, "square.nc")
        open(src, "w").write(PROGRAM)
        outputs = {}
        for ext in ("svg", "html"):
            out = os.path.join(work, "square." + ext)
            r = subprocess.run([tape, "plot", src, "-o", out, "--width", str(WIDTH), "--height", str(HEIGHT)],
                               capture_output=True, text=True, timeout=60)
            if r.returncode == 3 and "cairo" in r.stderr:
                print("SKIP: " + r.stderr.strip())
                return SKIP
            if r.returncode != 0:
                print(f"FAIL: tape plot -o {ext}: exit {r.returncode}: {r.stderr}")
                return 1
            outputs[ext] = out
        page = open(outputs["html"]).read()
        m = re.search(r'data-x0="([-\d.]+)" data-y0="([-\d.]+)" data-scale="([-\d.]+)"', page)
        if not m:
            print("FAIL: the page does not say where the part is (data-x0, data-y0, data-scale)")
            return 1
        x0, y0, scale = map(float, m.groups())
        for block in ("N40 G01 X100.", "N110 G02 X30. Y25. I-20. J0"):
            if f"<title>{block} (line" not in page:
                failures.append(f"no stroke names {block!r} on hover")
        dom, console = console_messages(chromium, outputs["html"])
        if console:
            failures.append(f"console messages: {console[:3]}")
        for ext, out in outputs.items():
            png = os.path.join(work, ext + ".png")
            status, err = screenshot(chromium, out, png, WIDTH, HEIGHT)
            if not os.path.exists(png):
                print(f"SKIP: chromium could not start or draw (exit {status}): {err.strip()[-400:]}")
                return SKIP
            w, h, rows = read_png(png)

            def pixel(u, v):
                # The pixel whose square lies inside the 2-pixel-wide stroke centred on the point.
                return rows[int(y0 - v * scale)][int(x0 + u * scale)]

            def is_tool(p):
                return sum((a - b) ** 2 for a, b in zip(p, TOOL)) < 60 ** 2

            def is_paper(p):
                return min(p) > 240

            for u, v in ((50, 0), (100, 20), (50, 50), (0, 30), (50, 5)):
                if not is_tool(pixel(u, v)):
                    failures.append(f"{ext}: ({u}, {v}) mm: the toolpath expected, pixel {pixel(u, v)}")
            for u, v in ((50, 45), (20, 15), (80, 40)):
                if not is_paper(pixel(u, v)):
                    failures.append(f"{ext}: ({u}, {v}) mm: paper expected, pixel {pixel(u, v)}")
            print(f"{ext}: {w}x{h} screenshot, the square and the half circle where they are")
    for f in failures:
        print("FAIL: " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
