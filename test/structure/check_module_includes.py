#!/usr/bin/env python3
"""Checks that the modules include one another in one direction only (docs/design.md, the module
table): a file of module M (include/ship_lrm/M/, src/M/) may include the headers of M and of the
modules M depends on, and nothing else; no file outside the ROS layer includes a ROS header or a
generated message. Run by ctest as Structure.ModuleIncludes; Structure.CheckerFindsUpwardIncludes
plants violations in a small tree to show that it fails.

Usage: check_module_includes.py REPOSITORY_ROOT. Exits 1 and lists every include that breaks the
direction.
"""
import os
import re
import sys

# Which modules each module may include (besides itself): the order of docs/design.md's table.
ALLOWED = {
    "common": set(),
    "lbm": {"common"},
    "rotor": {"common", "lbm"},
    "flight": {"common", "lbm", "rotor"},
    "wake": {"common", "lbm"},
    "lrm": {"common", "lbm", "rotor", "flight", "wake"},  # its scenario part (the approach) composes them
    "tools": {"common", "lbm", "rotor", "flight", "wake", "lrm"},
    "ros": {"common", "lbm", "rotor", "flight", "wake", "lrm"},
}
PROJECT_INCLUDE = re.compile(r'^\s*#\s*include\s*"ship_lrm/([A-Za-z_]+)(/|\.h")', re.M)
ROS_INCLUDE = re.compile(r'^\s*#\s*include\s*[<"](ros|nodelet|pluginlib|tf2_ros|diagnostic_updater|[a-z_]+_msgs)/', re.M)
SOURCE = (".hpp", ".h", ".cpp", ".cu", ".cuh")


def module_files(root):
    for base, module_of in (("include/ship_lrm", None), ("src", None)):
        top = os.path.join(root, base)
        if not os.path.isdir(top):
            continue
        for module in sorted(os.listdir(top)):
            folder = os.path.join(top, module)
            if not os.path.isdir(folder):
                continue
            for dirpath, _, names in os.walk(folder):
                for name in sorted(names):
                    if name.endswith(SOURCE):
                        yield module, os.path.relpath(os.path.join(dirpath, name), root)


def findings(root):
    out = []
    for module, path in module_files(root):
        if module not in ALLOWED:
            out.append(f"{path}: module '{module}' is not in the module table")
            continue
        with open(os.path.join(root, path), encoding="utf-8", errors="replace") as f:
            text = f.read()
        for m in PROJECT_INCLUDE.finditer(text):
            target, generated = m.group(1), m.group(2) == '.h"'
            line = text.count("\n", 0, m.start()) + 1
            if generated:
                if module != "ros":
                    out.append(f"{path}:{line}: includes the generated ROS message ship_lrm/{target}.h outside the ROS layer")
            elif target != module and target not in ALLOWED[module]:
                out.append(f"{path}:{line}: {module} includes {target} (allowed: {', '.join(sorted(ALLOWED[module])) or 'none'})")
        if module != "ros":
            for m in ROS_INCLUDE.finditer(text):
                line = text.count("\n", 0, m.start()) + 1
                out.append(f"{path}:{line}: includes a ROS header ({m.group(1)}/...) outside the ROS layer")
    return out


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    problems = findings(sys.argv[1])
    for p in problems:
        print(p)
    count = sum(1 for _ in module_files(sys.argv[1]))
    print(f"check_module_includes: {count} files, {len(problems)} includes against the direction")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
