#!/usr/bin/env python3
"""Runs check_docs.py on small repositories with one planted defect each (and on a clean one), so
that a checker which stopped finding a kind of defect fails here (ctest: Docs.CheckerFindsDefects).

Usage: test_check_docs.py [PATH_TO_check_docs.py]. Exits 1 naming every case that went wrong.
"""
import os
import subprocess
import sys
import tempfile

CHECKER = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "check_docs.py"))
WORD = "sess" + "ion"  # built from parts so that this file passes the check itself
DESIGN = "design" + ".md"  # likewise: the planted citations must not cite the real page

CLEAN = {
    "README.md": "# Tool\n\nSee [the design](docs/design.md#slip-edges) and `docs/design.md`.\n",
    "docs/design.md": "# Design\n\n## lbm\n\n### Slip edges\n\nText.\n\n### Walls that move\n\nText.\n",
    "src/a.cpp": f'// The rule (docs/{DESIGN}, "Slip edges"); the walls ({DESIGN}, "Walls\n// that move").\nint a;\n',
}

CASES = {
    "numbering on one line": ({"src/b.cpp": f"// fixed in {WORD} 12\n"}, "development-log numbering"),
    "numbering across a comment's line break": ({"src/b.cpp": f"// fixed in {WORD}\n// 12: faster\n"},
                                                "development-log numbering"),
    "numbering in a file name": ({f"docs/results/{WORD}_3.csv": "a,b\n"}, "in the file name"),
    "README too long": ({"README.md": "# Tool\n" + "line\n" * 150}, "more than 150"),
    "link to a missing file": ({"docs/extra.md": "# Extra\n\n[x](missing.md)\n"}, "no such file"),
    "link to a missing heading": ({"docs/extra.md": "# Extra\n\n[x](design.md#no-such)\n"}, "no such heading"),
    "cited path missing": ({"docs/extra.md": "# Extra\n\nRun `scripts/none.sh`.\n"}, "does not exist"),
    "cited Markdown file missing": ({"docs/extra.md": "# Extra\n\nSee ARCH.md.\n"}, "not in the repository"),
    "section citation that is no heading": ({"src/c.cpp": f'// see docs/{DESIGN}, "Slip corners"\n'},
                                            "which is no heading there"),
    "section citation across a line break": ({"src/c.cpp": f'// see docs/{DESIGN}, "Walls\n// that stand"\n'},
                                             "which is no heading there"),
}


def run(files):
    with tempfile.TemporaryDirectory() as d:
        for path, text in files.items():
            full = os.path.join(d, path)
            os.makedirs(os.path.dirname(full), exist_ok=True)
            with open(full, "w", encoding="utf-8") as f:
                f.write(text)
        subprocess.run(["git", "init", "-q", d], check=True)
        subprocess.run(["git", "-C", d, "add", "-A"], check=True)
        out = subprocess.run([sys.executable, CHECKER, d], capture_output=True, text=True)
        return out.returncode, out.stdout + out.stderr


def main():
    failures = []
    rc, out = run(CLEAN)
    if rc != 0:
        failures.append(f"clean repository reported:\n{out}")
    for name, (extra, expect) in CASES.items():
        rc, out = run({**CLEAN, **extra})
        if rc == 0 or expect not in out:
            failures.append(f"{name}: expected a finding with '{expect}', got rc {rc}:\n{out}")
    for f in failures:
        print("FAIL", f)
    print(f"test_check_docs: {len(CASES) + 1 - len(failures)} of {len(CASES) + 1} cases as expected")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
