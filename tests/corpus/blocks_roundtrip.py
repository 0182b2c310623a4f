#!/usr/bin/env python3
"""Every program of the corpus through `tape blocks --json`: every character accounted for.

    blocks_roundtrip.py TAPE CORPUS_DIR

For each NAME.nc, in the dialect its NAME.expect names and in auto: every non-blank line is a '%'
line, label, text after the end, or the blocks that stand on it; and each block's non-blank
characters are those of its number, words, comments and statements, give or take the delimiters
('/', its skip level, '(', ')', ';'). Exit 1 with the differences when anything is unaccounted for.
"""
import collections
import glob
import json
import os
import subprocess
import sys


def chars(s):
    return collections.Counter(c for c in s if c not in " \t\r\n")


def check_block(b):
    pieces = ([b["number"]] if b["number"] else []) + b["words"] + [s["text"] for s in b["statements"]]
    have = chars("".join(pieces) + "".join(b["comments"]))
    want = chars(b["source"])
    if b["skip"]:
        want["/"] -= 1
        if b["skip_level"]:
            want[str(b["skip_level"])] -= 1
    extra_in_source = {c: n for c, n in (want - have).items() if c not in "();"}
    extra_in_pieces = dict(have - want)
    problems = []
    if extra_in_source:
        problems.append("in the source but in no word, comment or statement: %r" % extra_in_source)
    if extra_in_pieces:
        problems.append("in words, comments or statements but not in the source: %r" % extra_in_pieces)
    return problems


def check(tape, path, dialect):
    run = subprocess.run([tape, "blocks", "--json", "--input", "text", "--dialect", dialect, path],
                         capture_output=True, text=True, timeout=60)
    if run.returncode != 0:
        return ["exit %d: %s" % (run.returncode, run.stderr.strip())]
    doc = json.loads(run.stdout)
    problems = []
    covered = collections.defaultdict(str)  # line -> the block sources on it
    for program in doc["programs"]:
        for b in program["blocks"]:
            covered[b["line"]] += b["source"]
            problems += ["line %d: %s" % (b["line"], p) for p in check_block(b)]
    text_lines = open(path, encoding="utf-8").read().split("\n")
    accounted = chars(doc["label"]) + chars("".join(p["after_end"] for p in doc["programs"]))
    for n, line in enumerate(text_lines, 1):
        if not line.strip():
            continue
        if n in covered:
            rest = chars(line) - chars(covered[n])
            if any(c != ";" for c in rest):
                problems.append("line %d: not in its blocks: %r" % (n, dict(rest)))
            continue
        if line.strip().startswith("%"):
            continue
        line_chars = chars(line)
        if line_chars - accounted:
            problems.append("line %d: in no block, label or text after the end: %r" % (n, line))
        else:
            accounted -= line_chars
    return problems


def main():
    tape, corpus = sys.argv[1], sys.argv[2]
    failed = 0
    programs = sorted(glob.glob(os.path.join(corpus, "*.nc")))
    for path in programs:
        expect = open(path[:-3] + ".expect", encoding="utf-8").read()
        dialect = next(l.split(":", 1)[1].strip() for l in expect.splitlines() if l.startswith("dialect:"))
        for d in (dialect, "auto"):
            for p in check(tape, path, d):
                print("%s (--dialect %s): %s" % (os.path.basename(path), d, p))
                failed += 1
    print("%d programs, %d problems" % (len(programs), failed))
    return 1 if failed or not programs else 0


if __name__ == "__main__":
    sys.exit(main())
