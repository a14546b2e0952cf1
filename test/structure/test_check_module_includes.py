#!/usr/bin/env python3
"""Runs check_module_includes.py on small trees with one planted upward include each (and on a clean
one), so that a checker which stopped finding one fails here (ctest: Structure.CheckerFindsUpwardIncludes).

Usage: test_check_module_includes.py [PATH_TO_check_module_includes.py]. Exits 1 naming every case
that went wrong.
"""
import os
import subprocess
import sys
import tempfile

CHECKER = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "check_module_includes.py"))

CLEAN = {
    "include/ship_lrm/common/vec.hpp": "#pragma once\n#include <Eigen/Core>\n",
    "include/ship_lrm/lbm/solver.hpp": '#pragma once\n#include "ship_lrm/common/config_error.hpp"\n#include "ship_lrm/lbm/lattice.hpp"\n',
    "include/ship_lrm/wake/table.hpp": '#pragma once\n#include "ship_lrm/lbm/solver.hpp"\n',
    "src/lrm/domain.cpp": '#include "ship_lrm/rotor/inflow_model.hpp"\n#include "ship_lrm/wake/table.hpp"\n',
    "src/ros/node.cpp": '#include <ros/ros.h>\n#include "ship_lrm/RotorLoads.h"\n#include "ship_lrm/lrm/domain.hpp"\n',
}

CASES = {
    "the LBM core includes the rotor": ({"src/lbm/solver.cpp": '#include "ship_lrm/rotor/inflow_model.hpp"\n'}, "lbm includes rotor"),
    "a header of common includes lbm": ({"include/ship_lrm/common/errors.hpp": '#include "ship_lrm/lbm/lattice.hpp"\n'},
                                        "common includes lbm"),
    "the wake includes the LRM": ({"include/ship_lrm/wake/feed.hpp": '  #  include "ship_lrm/lrm/domain.hpp"\n'}, "wake includes lrm"),
    "the tool includes the ROS layer": ({"src/tools/main.cpp": '#include "ship_lrm/ros/conversions.hpp"\n'}, "tools includes ros"),
    "a core file includes ROS": ({"src/flight/trim.cpp": "#include <ros/ros.h>\n"}, "a ROS header"),
    "a core file includes a message": ({"src/lrm/inflow.cpp": '#include "ship_lrm/RotorInflow.h"\n'}, "generated ROS message"),
    "a folder outside the table": ({"src/extra/a.cpp": "int a;\n"}, "not in the module table"),
}


def run(files):
    with tempfile.TemporaryDirectory() as root:
        for path, text in files.items():
            full = os.path.join(root, path)
            os.makedirs(os.path.dirname(full), exist_ok=True)
            with open(full, "w") as f:
                f.write(text)
        r = subprocess.run([sys.executable, CHECKER, root], capture_output=True, text=True)
        return r.returncode, r.stdout + r.stderr


def main():
    failed = []
    rc, out = run(CLEAN)
    if rc != 0:
        failed.append(f"the clean tree was refused:\n{out}")
    for name, (planted, expected) in CASES.items():
        rc, out = run({**CLEAN, **planted})
        if rc != 1 or expected not in out:
            failed.append(f"{name}: exit {rc}, wanted 1 and '{expected}':\n{out}")
    for f in failed:
        print("FAILED:", f)
    print(f"test_check_module_includes: {len(CASES) + 1 - len(failed)} of {len(CASES) + 1} cases right")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
