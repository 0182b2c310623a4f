#!/usr/bin/env python3
"""Every numeric option of every program refuses what is not a finite number in its range.

    numeric_options.py [--shard=K/N] TAPE TAPE_DAMAGE TAPE_ADAPTER_SIM

--shard=K/N tries only the K-th of every N options (K from 0): CTest runs the N shards side by side, each
within its own time limit (some 1500 process starts in all, minutes under AddressSanitizer).

The options are found in each (sub)command's --help by their type (INT, UINT, FLOAT), so an option added
tomorrow is tried too. Each is given values that are no number of its kind (nan, inf, 1e999, 0x10, +3,
12abc, ' 3', 1.5 for whole numbers, -1 for unsigned ones); each must end with status 2 and the
message of tools/cli/numbers ("... not 'VALUE'"), never be taken or reach a conversion."""
import re
import subprocess
import sys

OPTION = re.compile(r"^\s+(?:-\w,)?(--[\w-]+)(?:,-\w)? (INT|UINT|FLOAT)(:\S+)?")


def help_text(command):
    return subprocess.run(command + ["--help"], capture_output=True, text=True, timeout=30).stdout


def subcommands(command):
    text = help_text(command)
    if "Subcommands:" not in text:
        return []
    names = []
    for line in text.split("Subcommands:", 1)[1].splitlines():
        m = re.match(r"^  (\w[\w-]*)\s", line)
        if m:
            names.append(m.group(1))
        elif line.strip() and not line.startswith("   "):
            break
    return names


def commands(program):
    found, todo = [], [[program]]
    while todo:
        command = todo.pop()
        found.append(command)
        todo.extend(command + [name] for name in subcommands(command))
    return found


def bad_values(kind, check):
    values = ["nan", "-nan", "inf", "1e999", "12abc", " 3", "3 "]
    if kind != "INT":
        values += ["+3"]
    if "MASK" not in check:
        values += ["0x10"]
    if kind != "FLOAT":
        values += ["1.5", "1e3"]
    if kind == "UINT":
        values += ["-1"]
    return values


def main():
    args, shard, shards = sys.argv[1:], 0, 1
    if args and args[0].startswith("--shard="):
        shard, shards = (int(n) for n in args.pop(0).split("=", 1)[1].split("/"))
    failures, tried, index = [], 0, -1
    for program in args:
        for command in commands(program):
            for line in help_text(command).splitlines():
                m = OPTION.match(line)
                if not m:
                    continue
                index += 1
                if index % shards != shard:
                    continue
                option, kind, check = m.group(1), m.group(2), m.group(3) or ""
                for value in bad_values(kind, check):
                    tried += 1
                    r = subprocess.run(command + [option + "=" + value], capture_output=True, text=True, timeout=30,
                                       stdin=subprocess.DEVNULL)
                    said = "not '" + value + "'" in r.stderr
                    if r.returncode != 2 or not said:
                        failures.append(" ".join(command[1:] + [option + "=" + repr(value)]) +
                                        f": status {r.returncode}: {r.stderr.strip()[:200]}")
    for f in failures:
        print("taken or not refused as a number:", f)
    print(f"{tried} bad values tried, {len(failures)} not refused")
    return 1 if failures or tried < 100 // shards else 0


if __name__ == "__main__":
    sys.exit(main())
