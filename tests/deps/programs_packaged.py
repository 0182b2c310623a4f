#!/usr/bin/env python3
"""Every program the golden CLI cases and the shell scripts call comes from a package a fresh Debian has
(priority required: what debootstrap's minbase installs) or one scripts/install-deps.sh installs, or is
a bash builtin. A program present on the developers' machines but installed by nothing is what a green
CI on a used machine hides (xxd, hexdump).

Usage: programs_packaged.py REPO
The programs are found by reading the shell text (commands at the start of a simple command, in
pipelines, lists, $(...) and `...`), then mapped to their package with dpkg -S. Exit 77 (skipped) where
there is no dpkg: the mapping needs Debian's package database.
"""
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

# Words after which the next word is a command again.
SEPARATORS = {";", "|", "||", "&&", "&", "(", "\n", "{", "!", "if", "then", "else", "elif", "do", "while", "until",
              "time", "|&"}
REDIRECTIONS = {"<", ">", ">>", ">&", "<&", "<<<", "&>", "&>>", ">|", "<<", "<<-"}
OPERATOR_CHARS = ";|&()<>\n"
# Programs that run the command given after their options and assignments, with their options that take
# a value as the next word (timeout: its duration too).
WRAPPERS = {"env": {"-u", "--unset", "-C", "--chdir"}, "exec": {"-a"}, "command": set(), "nice": {"-n"},
            "nohup": set(), "timeout": {"-s", "--signal", "-k", "--kill-after"}, "timeout-duration": set(),
            "xargs": {"-n", "-I", "-d", "-P", "-L", "-s", "-a", "-E"}, "sudo": {"-u", "-g"}, "stdbuf": set()}
# The project's own programs (built, or installed by the package test) and what a test sources.
OWN = {"tape", "tape-damage", "tape-adapter-sim", "_tape"}
# Called only after the script has looked for it (command -v) and says what to do without it.
OPTIONAL = {
    "sudo": "install-deps.sh uses it only when not root and says what to run as root without it",
    "clang-format": "check-format.sh's second choice, after clang-format-14",
    "git": "check-format.sh lists the files with git in a clone, with find otherwise",
}


def builtins():
    out = subprocess.run(["bash", "-c", "compgen -b; compgen -k"], capture_output=True, text=True, check=True)
    return set(out.stdout.split())


def substitutions(text):
    """The text with each $(...), <(...), >(...), `...` and $((...)) replaced by a word, and the commands
    taken out."""
    inner, out, i = [], [], 0
    while i < len(text):
        if text[i] == "`":
            end = text.find("`", i + 1)
            end = len(text) if end < 0 else end
            inner.append(text[i + 1:end])
            out.append(" SUBST ")
            i = end + 1
        elif text[i] in "$<>" and text.startswith("(", i + 1):
            depth, j = 1, i + 2
            while j < len(text) and depth:
                depth += {"(": 1, ")": -1}.get(text[j], 0)
                j += 1
            if not text.startswith("$((", i):  # $((...)) is arithmetic
                inner.append(text[i + 2:j - 1])
            out.append("SUBST")
            i = j
        else:
            out.append(text[i])
            i += 1
    return "".join(out), inner


def tokens(text):
    """Words and operators; a run of operators is split into the operators bash reads."""
    lexer = shlex.shlex(text, posix=True, punctuation_chars=";|&()<>\n")
    lexer.whitespace = " \t\r"
    lexer.commenters = ""
    lexer.whitespace_split = True
    try:
        words = list(lexer)
    except ValueError:  # a quote the simple lexer misreads: that file is read line by line
        words = []
        for line in text.splitlines():
            try:
                words += tokens_of_line(line) + ["\n"]
            except ValueError:
                words.append("\n")
    split = []
    for w in words:
        if w and set(w) <= set(OPERATOR_CHARS):
            split += re.findall(r";;&?|;&|\|\||&&|\|&|&>>?|<<<|<<-?|>>|[<>]&|>\||[;|&()<>\n]", w)
        else:
            split.append(w)
    return split


def tokens_of_line(line):
    lexer = shlex.shlex(line, posix=True, punctuation_chars=";|&()<>")
    lexer.whitespace_split = True
    lexer.commenters = ""
    return list(lexer)


def without_comments(text):
    """Each line without its comment: a '#' starting a word outside quotes (as far as one line tells)."""
    lines = []
    for line in text.splitlines():
        for m in re.finditer(r"(?:^|(?<=\s))#", line):
            before = line[:m.start()]
            if before.count("'") % 2 == 0 and before.count('"') % 2 == 0:
                line = before
                break
        lines.append(line)
    return "\n".join(lines) + "\n"


# What follows a word that opens a construct whose words up to the closing one are no commands.
SKIPPED_UP_TO = {"[[": {"]]"}, "for": {"\n", ";", "do"}, "select": {"\n", ";", "do"}, "((": {")"}}


def skipped_up_to(words, k):
    """The words ending a stretch that holds no command, starting at words[k], or None."""
    w = words[k]
    if w in (";;", ";&", ";;&") or (w == "in" and k >= 2 and words[k - 2] == "case"):
        return {")"}  # a case pattern
    if w == "for" and words[k + 1:k + 3] == ["(", "("]:
        return {"do"}  # for ((...; ...; ...))
    if w == "(" and words[k + 1:k + 2] == ["("]:
        return SKIPPED_UP_TO["(("]  # arithmetic
    if re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*\+?=", w) and words[k + 1:k + 2] == ["("]:
        return {")"}  # an array assignment
    return SKIPPED_UP_TO.get(w)


def commands(text, found):
    """Adds to the set found the names in command position of a shell text, and "function NAME" for
    each function it defines."""
    text, inner = substitutions(re.sub(r"\\\n", " ", text))
    for part in inner:
        commands(part, found)
    words = tokens(text)
    at_command, skip_to, skip_next, wrapped = True, None, False, None
    for k, w in enumerate(words):
        if skip_next or (skip_to and w not in skip_to):
            skip_next = False
            continue
        if skip_to or w in SEPARATORS:
            skip_to, at_command = None, True
            continue
        if w in REDIRECTIONS:
            skip_next = True  # its file, descriptor or here-string
            continue
        if w in (")", "}", "case"):
            at_command = False  # a redirection or a separator comes next; case: its word
            continue
        skip_to = (at_command or w in (";;", ";&", ";;&", "in")) and skipped_up_to(words, k)
        if skip_to or not at_command or re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*(\[[^]]*\])?\+?=.*", w, flags=re.S):
            continue  # in a construct, an argument, an assignment before the command
        if wrapped == "timeout" and not w.startswith("-"):
            wrapped = "timeout-duration"
            continue
        if re.fullmatch(r"\d+", w) or (wrapped and w.startswith("-")):
            skip_next = bool(wrapped) and w in WRAPPERS[wrapped]
            continue  # a redirection's descriptor before the command; a wrapper's option (and its value)
        if words[k + 1:k + 3] == ["(", ")"]:
            found.add("function " + w)
            skip_next = True
            continue
        found.add(w)
        wrapped = w if w in WRAPPERS else None
        at_command = bool(wrapped)


def programs(path):
    found = set()
    text = path.read_text(encoding="utf-8")
    # Heredoc bodies are data, not commands.
    text = re.sub(r"<<-?\s*'?\"?(\w+)'?\"?[^\n]*\n.*?\n\s*\1\n", "\n", text, flags=re.S)
    commands(without_comments(text), found)
    functions = {n.split(" ", 1)[1] for n in found if n.startswith("function ")}
    return {n for n in found if not n.startswith("function ") and n not in functions}


def package_lists(install_deps):
    text = install_deps.read_text(encoding="utf-8")
    listed = set()
    for body in re.findall(r"^[a-z]+=\(\n(.*?)^\)", text, flags=re.S | re.M):
        listed |= {line.split("#")[0].strip() for line in body.splitlines()} - {""}
    return listed


def with_dependencies(packages):
    """The packages and what apt installs with them: their Depends and Pre-Depends, each group's first
    choice (apt's), as the installed packages' records say."""
    have, todo = set(), set(packages)
    while todo:
        have |= todo
        out = subprocess.run(["dpkg-query", "-W", "-f", "${Pre-Depends}, ${Depends}\n", *sorted(todo)],
                             capture_output=True, text=True)
        todo = set()
        for group in out.stdout.replace("\n", ",").split(","):
            first = group.split("|")[0].split("(")[0].strip().split(":")[0]
            if first and first not in have:
                todo.add(first)
    return have


def packages_of(programs):
    """For each program: its path and the package holding it (path None: not installed; package None:
    in no package). One dpkg -S for all: it reads the whole file database at each call."""
    paths, candidates = {}, {}
    for program in programs:
        path = shutil.which(program)
        paths[program] = path
        if not path:
            continue
        real = str(Path(path).resolve())
        # An interpreter of one's own earlier on the PATH (pyenv) does not say which package the system has;
        # merged /usr: dpkg knows /bin/sh, not /usr/bin/sh.
        candidates[program] = [path, real, "/usr/bin/" + program, "/bin/" + program]
        for p in (path, real):
            for usr, root in (("/usr/bin/", "/bin/"), ("/usr/sbin/", "/sbin/")):
                if p.startswith(usr):
                    candidates[program].append(root + p[len(usr):])
    every = sorted({c for cs in candidates.values() for c in cs})
    out = subprocess.run(["dpkg", "-S", *every], capture_output=True, text=True) if every else None
    owner = {}
    for line in out.stdout.splitlines() if out else []:
        if line.startswith("diversion ") or ": " not in line:
            continue
        owners, owned = line.split(": ", 1)
        owner.setdefault(owned, owners.split(",")[0].split(":")[0].strip())
    result = {}
    for program, path in paths.items():
        package = next((owner[c] for c in candidates.get(program, []) if c in owner), None)
        result[program] = (path, package)
    return result


def main():
    repo = Path(sys.argv[1])
    if not shutil.which("dpkg") or not shutil.which("dpkg-query"):
        print("programs_packaged: skipped: no dpkg here to say which package holds a program")
        return 77
    listed = with_dependencies(package_lists(repo / "scripts" / "install-deps.sh"))
    skip = builtins()
    files = sorted((repo / "tests" / "cli" / "cases").glob("*.cmd"))
    files += sorted((repo / "scripts").glob("*.sh")) + sorted((repo / "tests").glob("**/*.sh"))
    callers = {}
    for f in files:
        for program in programs(f):
            if program.startswith(("$", "-", "SUBST")) or "/" in program or program in skip | OWN:
                continue
            callers.setdefault(program, []).append(str(f.relative_to(repo)))
    problems, priorities = [], {}
    found = packages_of(sorted(set(callers) - set(OPTIONAL)))
    for program, (path, package) in sorted(found.items()):
        where = ", ".join(callers[program][:3]) + (" …" if len(callers[program]) > 3 else "")
        if path is None:
            problems.append(f"{program} (called by {where}): not installed here; add the package that has it "
                            "to scripts/install-deps.sh")
            continue
        if not package:
            problems.append(f"{program} (called by {where}): {path} belongs to no Debian package")
            continue
        if package in listed:
            continue
        if package not in priorities:
            out = subprocess.run(["dpkg-query", "-W", "-f", "${Priority} ${Essential}", package],
                                 capture_output=True, text=True)
            priorities[package] = out.stdout.split()
        if "required" in priorities[package] or "yes" in priorities[package]:
            continue
        problems.append(f"{program} (called by {where}): its package {package} is not in scripts/install-deps.sh "
                        "and a fresh Debian does not have it (priority "
                        f"{' '.join(priorities[package][:1]) or 'unknown'})")
    for p in problems:
        print("programs_packaged: " + p)
    print(f"programs_packaged: {len(callers)} programs called by {len(files)} files, {len(problems)} not installed "
          "by a fresh Debian or install-deps.sh")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
