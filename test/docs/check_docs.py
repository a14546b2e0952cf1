#!/usr/bin/env python3
"""Checks the documentation as a product (run by ctest as Docs.Check):

1. no tracked file (contents or path) carries development-log numbering: the words session, issue or
   acceptance followed by a number, also where a line break (and a comment marker) falls between;
2. README.md has at most 150 lines;
3. every relative link in README.md and docs/ resolves to a file of the repository, and a link's
   #anchor to a heading of the linked Markdown page (GitHub's heading slugs);
4. every repository path cited in backticks in README.md and docs/ exists, and no Markdown file is
   named that the repository does not hold;
5. every section a tracked file cites by name in a page of docs/ (`docs/design.md, "Slip edges"`,
   also across a comment's line break) is a heading of that page, or the start of one. A citation
   of a page at a commit (`docs/benchmarks.md at 193c1b4, "..."`) names the page as it was then
   and is not checked.

Usage: check_docs.py REPOSITORY_ROOT. Exits 1 and lists every finding when one check fails.
"""
import os
import re
import subprocess
import sys

# Built from parts so that this file does not match itself.
NUMBERING = re.compile(r"\b(" + "sess" + "ions?|" + "iss" + "ues?|" + "accept" + r"ances?)[ _-]?#?[0-9]", re.I)
CONTINUATION = re.compile(r"^\s*(//+|#+|\*+|--|;+|%+|>+)?\s*")
FLATTEN = re.compile(r"\n[ \t]*(?://+|#+|\*+|--|;+|%+|>+)?[ \t]*")
SECTION = re.compile(r'(?<![\w/.-])((?:docs/)?(?:reference/)?[\w]+\.md)(?: at [0-9a-f]{7,40})?[,:]?[ \t]+\\?"([^"\\\n]{2,100})\\?"')
LINK = re.compile(r"\[[^\]]*\]\(([^)\s]+)\)")
MD_NAME = re.compile(r"(?<![\w./:-])([\w./-]+\.md)\b")
CODE = re.compile(r"`([^`\n]+)`")
TOP = ("docs/", "scripts/", "config/", "include/", "src/", "test/", "launch/", "msg/", "srv/", "rviz/", ".ci/")
README_LIMIT = 150


def tracked_files(root):
    try:
        out = subprocess.run(["git", "-C", root, "ls-files", "-z"], check=True, capture_output=True).stdout
        files = [p for p in out.decode().split("\0") if p]
        if files:
            return files
    except (OSError, subprocess.CalledProcessError):
        pass
    # not a git checkout (a copy of the sources): every file but the build's
    files = []
    for d, dirs, names in os.walk(root):
        dirs[:] = [x for x in dirs if x not in (".git", "build", ".carry")]
        files += [os.path.relpath(os.path.join(d, n), root) for n in names]
    return files


def slug(heading):
    s = heading.strip().lower()
    s = re.sub(r"[`*_]", lambda m: "_" if m.group(0) == "_" else "", s)
    s = re.sub(r"[^\w\- ]", "", s)
    return s.replace(" ", "-")


def headings(path):
    """The text of every Markdown heading of a page (outside code blocks)."""
    result = []
    in_code = False
    for line in open(path, encoding="utf-8"):
        if line.startswith("```"):
            in_code = not in_code
        elif not in_code and line.startswith("#"):
            result.append(line.lstrip("#"))
    return result


def anchors(path):
    return {slug(h) for h in headings(path)}


def normal(text):
    return re.sub(r"\s+", " ", re.sub(r"[`*]", "", text)).strip().lower()


def heading_texts(path):
    return [normal(h) for h in headings(path)]


def doc_pages(files):
    return [f for f in files if f == "README.md" or f == "CHANGELOG.md" or (f.startswith("docs/") and f.endswith(".md"))]


def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else ".")
    # a catkin workspace's package folder links to the repository's entries: check the repository
    root = os.path.dirname(os.path.realpath(os.path.join(root, "README.md")))
    files = tracked_files(root)
    present = set(files)
    dirs = {os.path.dirname(f) for f in files}
    while "" in dirs:
        dirs.discard("")
    for d in list(dirs):
        while d:
            dirs.add(d)
            d = os.path.dirname(d)
    problems = []

    for f in files:
        if NUMBERING.search(f):
            problems.append(f"{f}: development-log numbering in the file name")
        full = os.path.join(root, f)
        if not os.path.isfile(full):
            continue
        try:
            text = open(full, encoding="utf-8").read()
        except UnicodeDecodeError:
            continue
        lines = text.split("\n")
        for n, line in enumerate(lines, 1):
            m = NUMBERING.search(line)
            if not m and n < len(lines):
                # the word at a line's end and its number on the next, after the comment marker
                joined = line.rstrip() + " " + CONTINUATION.sub("", lines[n])
                m = NUMBERING.search(joined, max(0, len(line.rstrip()) - 12))
            if m:
                problems.append(f"{f}:{n}: development-log numbering '{m.group(0)}'")

    readme = os.path.join(root, "README.md")
    lines = open(readme, encoding="utf-8").read().count("\n")
    if lines > README_LIMIT:
        problems.append(f"README.md: {lines} lines, more than {README_LIMIT}")

    for page in doc_pages(files):
        base = os.path.dirname(page)
        text = open(os.path.join(root, page), encoding="utf-8").read()
        for n, line in enumerate(text.split("\n"), 1):
            for target in LINK.findall(line):
                if re.match(r"^[a-z]+:", target):
                    continue
                path, _, anchor = target.partition("#")
                resolved = os.path.normpath(os.path.join(base, path)) if path else page
                if resolved not in present and resolved not in dirs:
                    problems.append(f"{page}:{n}: link to {target}: no such file")
                elif anchor and resolved.endswith(".md") and anchor not in anchors(os.path.join(root, resolved)):
                    problems.append(f"{page}:{n}: link to {target}: no such heading")
            for token in CODE.findall(line):
                for word in token.split():
                    word = word.strip("\"',;:()")
                    if re.search(r"[*<>{}$|]|\.\.\.|FILE|DIR|OUT", word):
                        continue
                    if word.startswith(TOP):
                        p = word.rstrip("/")
                        if p not in present and p not in dirs:
                            problems.append(f"{page}:{n}: cited path {word} does not exist")
            for word in MD_NAME.findall(LINK.sub("", line)):
                cands = {os.path.normpath(os.path.join(base, word)), word, "docs/" + word}
                if not cands & present:
                    problems.append(f"{page}:{n}: cited file {word} is not in the repository")

    headings = {}
    for f in files:
        full = os.path.join(root, f)
        if not os.path.isfile(full) or f.startswith("docs/results/"):
            continue
        try:
            text = open(full, encoding="utf-8").read()
        except UnicodeDecodeError:
            continue
        if ".md" not in text:
            continue
        flat = FLATTEN.sub(" ", text)
        for m in SECTION.finditer(flat):
            if " at " in m.group(0).split('"')[0]:
                continue
            name = m.group(1)
            page = next((c for c in (name, "docs/" + name, os.path.normpath(os.path.join(os.path.dirname(f), name)))
                         if c in present and c.startswith("docs/")), None)
            if page is None:
                continue
            if page not in headings:
                headings[page] = heading_texts(os.path.join(root, page))
            cited = normal(m.group(2))
            if not any(h.startswith(cited) for h in headings[page]):
                line = flat.count("\n", 0, m.start()) + 1
                problems.append(f"{f}: cites {name}, \"{m.group(2)}\", which is no heading there (near line {line})")

    for p in problems:
        print(p)
    if problems:
        print(f"check_docs: {len(problems)} problem(s)")
        return 1
    print(f"check_docs: {len(files)} tracked files, {len(doc_pages(files))} pages: no problem")
    return 0


if __name__ == "__main__":
    sys.exit(main())
