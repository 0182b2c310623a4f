#!/usr/bin/env python3
"""Prints the Pico pin table of firmware/rp2040/pins.hpp as the Markdown table docs/rp2040-wiring.md
carries between its "pins:begin" and "pins:end" marks; with --write, puts it there.
tests/rp2040/wiring_doc_test.py checks that the document holds what this prints.

Usage: rp2040-wiring.py [--write]"""
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
HEADER = os.path.join(ROOT, "firmware/rp2040/pins.hpp")
DOC = os.path.join(ROOT, "docs/rp2040-wiring.md")
BEGIN, END = "<!-- pins:begin (scripts/rp2040-wiring.py --write) -->", "<!-- pins:end -->"


def pins(text: str):
    """The rows of pico_pins::table, with its named shifting constants resolved."""
    names = dict(re.findall(r'inline constexpr const char\* (\w+) = "([^"]*)";', text))
    body = text[text.index("inline constexpr Pin table[] = {"):]
    body = body[:body.index("};")]
    rows = []
    for gpio, connector, signal, direction, shifting in re.findall(
            r'\{(\d+), "([^"]*)", "([^"]*)", Dir::(in|out), (\w+|"[^"]*")\}', body):
        shifting = shifting.strip('"') if shifting.startswith('"') else names[shifting]
        rows.append((int(gpio), connector, signal, direction, shifting))
    return rows


def table(rows) -> str:
    lines = ["| Pico pin | connector | signal | direction (Pico) | level shifting |", "|---|---|---|---|---|"]
    lines += [f"| GP{g} | {c} | {s} | {d} | {x} |" for g, c, s, d, x in rows]
    return "\n".join(lines) + "\n"


def main() -> int:
    with open(HEADER, encoding="utf-8") as f:
        text = table(pins(f.read()))
    if sys.argv[1:] == ["--write"]:
        with open(DOC, encoding="utf-8") as f:
            doc = f.read()
        start, end = doc.index(BEGIN) + len(BEGIN), doc.index(END)
        with open(DOC + ".tmp", "w", encoding="utf-8") as f:
            f.write(doc[:start] + "\n" + text + doc[end:])
        os.replace(DOC + ".tmp", DOC)
    elif sys.argv[1:]:
        print(__doc__.splitlines()[-1], file=sys.stderr)
        return 2
    else:
        sys.stdout.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
