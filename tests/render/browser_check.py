#!/usr/bin/env python3
"""The tape as a browser draws it: `tape render` output opened in headless Chromium, screenshot to PNG,
and the pixels looked at where the holes of a known tape are and where they are not; then the page of
`tape restore --html`: it loads with no console message (no script, nothing fetched), and each problem
frame of the JSON report in the first stretch of tape drawn (the page draws the tape around its problems
only) is marked in its colour, where the report says, and every problem row links to its frame.

Usage: browser_check.py TAPE_BINARY. Exit 0 passed, 1 failed, 77 skipped (Chromium missing or unable to
start: the reason is printed). Only the standard library: PNG read with zlib and struct.
"""
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

SKIP = 77
PX_PER_UNIT = 96 / 25.4 / 100  # CSS pixels per hundredth of a millimetre

# The drawing's geometry in hundredths of a millimetre (include/tape/render.hpp, svg_geometry).
PITCH, LEFT, LEGEND, NUMBERS, TAPE, CHARS, GAP = 254, 600, 700, 450, 2540, 450, 300
STRIP = NUMBERS + TAPE + CHARS + GAP


def hole_centre(n, track, per_strip, mirror=False):
    row = 6 if track == 0 else (9 - track if track >= 4 else 10 - track)
    if mirror:
        row = 10 - row
    strip, at = divmod(n, per_strip)
    return LEFT + at * PITCH + PITCH // 2, LEGEND + strip * STRIP + NUMBERS + row * PITCH


def read_png(path):
    """(width, height, rows of (r, g, b) tuples) of an 8-bit RGB or RGBA PNG."""
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG")
    pos, idat, width = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if depth != 8 or colour not in (2, 6) or interlace:
                raise ValueError(f"PNG depth {depth} colour type {colour} interlace {interlace}: not read here")
            channels = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
        elif kind == b"IEND":
            break
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, prev, i = [], bytearray(stride), 0
    for _ in range(height):
        ftype, line = raw[i], bytearray(raw[i + 1:i + 1 + stride])
        i += 1 + stride
        for x in range(stride):
            a = line[x - channels] if x >= channels else 0
            b = prev[x]
            c = prev[x - channels] if x >= channels else 0
            if ftype == 1:
                line[x] = (line[x] + a) & 255
            elif ftype == 2:
                line[x] = (line[x] + b) & 255
            elif ftype == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif ftype == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[x:x + 3]) for x in range(0, stride, channels)])
        prev = line
    return width, height, rows


def find_chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


def browser_env(profile):
    """The environment for Chromium: its home, configuration and cache in the profile's folder, which is
    removed after, since even with --user-data-dir it writes crash-report settings and a dconf cache
    under the user's home."""
    env = dict(os.environ)
    env.update(HOME=profile, XDG_CONFIG_HOME=os.path.join(profile, "config"),
               XDG_CACHE_HOME=os.path.join(profile, "cache"))
    return env


def screenshot(chromium, page, png, width, height, extra=()):
    """Chromium's picture of page; returns (exit status, stderr) or raises on its time limit."""
    profile = tempfile.mkdtemp(prefix="tape-chromium-")
    try:
        args = ["timeout", "60", chromium, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                "--no-first-run", "--disable-background-networking", "--disable-component-update", "--disable-sync",
                "--force-device-scale-factor=1", "--hide-scrollbars", f"--user-data-dir={profile}",
                f"--screenshot={png}", f"--window-size={width},{height}", *extra, "file://" + page]
        r = subprocess.run(args, capture_output=True, text=True, timeout=90, env=browser_env(profile))
        return r.returncode, r.stderr
    finally:
        shutil.rmtree(profile, ignore_errors=True)


GREEN = (153, 197, 138)  # the legend's colours at 45% over the paper
ORANGE = (237, 196, 118)
PAPER = (243, 230, 191)
RED = (234, 148, 124)


def nearest(p):
    colours = {"paper": PAPER, "restored": GREEN, "doubtful": ORANGE, "parity": RED}
    return min(colours, key=lambda k: sum((a - b) ** 2 for a, b in zip(p, colours[k])))


def console_messages(chromium, page):
    """Lines Chromium logs for the page's console (errors, CSP violations, failed loads)."""
    profile = tempfile.mkdtemp(prefix="tape-chromium-")
    try:
        args = ["timeout", "60", chromium, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                "--no-first-run", "--disable-background-networking", "--disable-component-update", "--disable-sync",
                "--enable-logging=stderr", "--v=0", f"--user-data-dir={profile}", "--dump-dom", "file://" + page]
        r = subprocess.run(args, capture_output=True, text=True, timeout=90, env=browser_env(profile))
        return r.stdout, [line for line in r.stderr.splitlines() if "CONSOLE" in line]
    finally:
        shutil.rmtree(profile, ignore_errors=True)


def check_restore_page(tape, chromium, work, failures):
    import json
    damage = os.path.join(os.path.dirname(tape), "tape-damage")
    sample = os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "..", "tapes",
                          "gost-20999-format-example.iso.ptp")
    # The console check must be able to fail: a page with a console error is seen to have one.
    control = os.path.join(work, "control.html")
    open(control, "w").write("<!DOCTYPE html><html><body><script>console.error('control')</script></body></html>")
    if not console_messages(chromium, control)[1]:
        failures.append("a console error on a control page was not seen: the console check sees nothing")
    cases = {"three": [11, 12, 13], "one": [5]}
    for name, seeds in cases.items():
        reads = []
        for seed in seeds:
            path = os.path.join(work, f"{name}-{seed}.ptp")
            damage_rate = "0.02" if len(seeds) > 1 else "0.03"
            subprocess.run([damage, sample, "-o", path, "--seed", str(seed), "--damage", damage_rate], check=True,
                           timeout=60)
            reads.append(path)
        page = os.path.join(work, f"{name}.html")
        report = os.path.join(work, f"{name}.json")
        r = subprocess.run([tape, "restore", *reads, "-o", os.path.join(work, f"{name}-out.ptp"), "--json",
                            "--report", report, "--html", page], timeout=60)
        if r.returncode not in (0, 1):
            failures.append(f"{name}: restore exit {r.returncode}")
            continue
        problems = [p for p in json.load(open(report))["problems"] if p["frame"]]
        dom, console = console_messages(chromium, page)
        if console:
            failures.append(f"{name}: console messages: {console[:3]}")
        for p in problems:
            if f'id="p{p["frame"]}"' not in dom or f'href="#f{p["frame"]}"' not in dom:
                failures.append(f"{name}: frame {p['frame']}: no table row linked to the tape")
        # The page draws the tape around its problems only: the first stretch drawn is looked at.
        import re
        first = re.search(r'id="tape1" data-from="(\d+)" data-to="(\d+)"', open(page).read())
        if not first:
            failures.append(f"{name}: no stretch of tape drawn")
            continue
        drawn_from, drawn_to = int(first.group(1)), int(first.group(2))
        problems = [p for p in problems if drawn_from <= p["frame"] <= drawn_to]
        png = os.path.join(work, f"{name}.png")
        screenshot(chromium, page, png, 1300, 1600)  # the page holds strips of 263 mm, 994 px
        w, h, rows = read_png(png)
        # The first strip's top-left corner: the first paper-coloured pixel from the top.
        corner = next(((x, y) for y in range(h) for x in range(w)
                       if all(abs(a - b) <= 3 for a, b in zip(rows[y][x], PAPER))), None)
        if corner is None:
            failures.append(f"{name}: no tape found in the screenshot")
            continue
        top_units = LEGEND + NUMBERS
        print(f"{name}: tape found at {corner} in a {w}x{h} screenshot")

        def at(frame, per_strip=100):
            # Between the tape's edge and track 8 (whose holes begin 1.62 mm in): no hole is ever there,
            # only the mark's colour.
            x, y = hole_centre(frame - drawn_from, 8, per_strip)
            y -= PITCH - 75
            return rows[corner[1] + round((y - top_units) * PX_PER_UNIT)][corner[0] + round((x - LEFT) * PX_PER_UNIT)]

        marked = set()
        for p in problems:
            want = "restored" if p["status"] in ("voted", "inferred") else "doubtful"
            got = nearest(at(p["frame"]))
            marked.add(p["frame"])
            if got != want:
                failures.append(f"{name}: frame {p['frame']} ({p['status']}): {want} mark expected, {got} {at(p['frame'])}")
        clean = [f for f in range(drawn_from + 1, drawn_to) if not ({f - 1, f, f + 1} & marked)]
        for f in clean:
            if nearest(at(f)) != "paper":
                failures.append(f"{name}: frame {f} (clean): paper expected, pixel {at(f)}")
        print(f"restore --html ({name} read(s)): {len(problems)} problem frames marked where the report says, "
              f"{len(clean)} clean frames unmarked, no console message")


def main():
    tape = os.path.realpath(sys.argv[1])
    chromium = find_chromium()
    if not chromium:
        print("SKIP: no chromium on PATH (scripts/install-deps.sh installs it)")
        return SKIP
    failures = []
    with tempfile.TemporaryDirectory(prefix="tape-render-") as work:
        # A known tape: every single track, all holes, none, and a few mixed frames.
        frames = bytes([0x00, 0xFF, 0x01, 0x02, 0x04, 0x08, 0x10, 0x20, 0x40, 0x80, 0x55, 0xAA, 0x00, 0x81, 0x3C])
        per_strip = 10  # --strip-length 25.4: the tape wraps after frame 10
        src = os.path.join(work, "known.ptp")
        open(src, "wb").write(frames)
        for mirror in (False, True):
            svg = os.path.join(work, f"known{'-mirror' if mirror else ''}.svg")
            cmd = [tape, "render", "--code", "none", "--strip-length", "25.4", src, "-o", svg]
            if mirror:
                cmd.append("--mirror")
            subprocess.run(cmd, check=True, timeout=60)
            strips = (len(frames) + per_strip - 1) // per_strip
            width = int(19000 * PX_PER_UNIT) + 2
            height = int((LEGEND + strips * STRIP) * PX_PER_UNIT) + 2
            png = os.path.join(work, "shot.png")
            status, err = screenshot(chromium, svg, png, width, height)
            if not os.path.exists(png):
                print(f"SKIP: chromium could not start or draw (exit {status}): {err.strip()[-400:]}")
                return SKIP
            w, h, rows = read_png(png)

            def pixel(x_units, y_units):
                return rows[round(y_units * PX_PER_UNIT)][round(x_units * PX_PER_UNIT)]

            def dark(p):
                return max(p) < 90

            def paper(p):
                return p[0] > 200 and p[1] > 190 and 140 < p[2] < 230 and p[0] > p[2] + 25

            checked = 0
            for n, f in enumerate(frames):
                for track in range(0, 9):
                    x, y = hole_centre(n, track, per_strip, mirror)
                    p = pixel(x, y)
                    holed = track == 0 or bool(f >> (track - 1) & 1)
                    if holed and not dark(p):
                        failures.append(f"mirror={mirror} frame {n + 1} track {track}: hole expected, pixel {p}")
                    if not holed and not paper(p):
                        failures.append(f"mirror={mirror} frame {n + 1} track {track}: paper expected, pixel {p}")
                    checked += 1
            # Between the strips there is no tape.
            gap = pixel(LEFT + PITCH, LEGEND + NUMBERS + TAPE + CHARS + GAP // 2)
            if gap != (255, 255, 255):
                failures.append(f"mirror={mirror}: white expected between strips, pixel {gap}")
            print(f"mirror={mirror}: {checked} hole and paper positions looked at in a {w}x{h} screenshot")

        # A parity error is shaded red where the legend says, between its holes.
        bad = os.path.join(work, "bad.ptp")
        open(bad, "wb").write(bytes([0x00, 0xA5, 0x25, 0x00]))  # frame 2 '%' even parity, frame 3 odd: bad
        svg = os.path.join(work, "bad.svg")
        subprocess.run([tape, "render", "--code", "iso", bad, "-o", svg], check=True, timeout=60)
        png = os.path.join(work, "bad.png")
        screenshot(chromium, svg, png, int(19000 * PX_PER_UNIT) + 2, int((LEGEND + STRIP) * PX_PER_UNIT) + 2)
        _, _, rows = read_png(png)
        x, y = hole_centre(2, 2, 100)  # frame 3, track 2: not punched, shaded
        shaded = rows[round(y * PX_PER_UNIT)][round(x * PX_PER_UNIT)]
        x, y = hole_centre(1, 2, 100)  # frame 2, track 2: not punched, plain paper
        plain = rows[round(y * PX_PER_UNIT)][round(x * PX_PER_UNIT)]
        if not (shaded[0] > shaded[1] + 40 and shaded[0] > shaded[2] + 40):
            failures.append(f"frame 3 (parity error): red shading expected, pixel {shaded}")
        if shaded == plain:
            failures.append("frame 3 (parity error) looks like frame 2 (good)")
        print(f"parity error shading {shaded}, good frame {plain}")
        check_restore_page(tape, chromium, work, failures)
    for f in failures[:40]:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
