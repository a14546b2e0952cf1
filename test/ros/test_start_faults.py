#!/usr/bin/python3
"""fault check, the faults at start: a missing wake table stops the run with a message that
names the command that makes it (`ship_lrm wake --preset default --out PATH`), and an invalid parameter
is refused at start with its name and range (or its choices), or its type. Each launch must end by itself (no
hang), and no process may die of a signal (a crash); roslaunch runs on a port of its own.

    test_start_faults.py TINY_TABLE.h5    (run through the workspace's devel/env.sh)"""
import os
import re
import socket
import subprocess
import sys
import tempfile


def free_port():
    with socket.socket() as s:
        s.bind(("localhost", 0))
        return s.getsockname()[1]


def launch(args, limit=120):
    """roslaunch approach.launch with args; its output, or a failure when it did not end in `limit` s."""
    port = free_port()
    env = dict(os.environ, ROS_MASTER_URI=f"http://localhost:{port}")
    cmd = ["roslaunch", "-p", str(port), "ship_lrm", "approach.launch", "backend:=cpu", "duration:=2", "startup:=0.1"] + args
    try:
        run = subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=limit, text=True)
    except subprocess.TimeoutExpired as e:
        out = e.output.decode() if isinstance(e.output, bytes) else (e.output or "")
        sys.exit(f"FAILED: {' '.join(args)}: the launch did not end within {limit} s:\n{out[-3000:]}")
    return run.stdout


def expect(out, what, pattern):
    if not re.search(pattern, out):
        sys.exit(f"FAILED: {what}: no line matches {pattern!r} in:\n{out[-4000:]}")
    crashed = re.findall(r"process has died \[pid \d+, exit code -\d+", out)
    if crashed:
        sys.exit(f"FAILED: {what}: a process died of a signal: {crashed}\n{out[-4000:]}")
    print(f"ok: {what}")


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    table = sys.argv[1]
    with tempfile.TemporaryDirectory() as tmp:
        missing = os.path.join(tmp, "no_such_table.h5")
        out = launch([f"wake_file:={missing}", "wake_source:=server", "N:=16"])
        expect(out, "missing wake table", r"WakeServer: wake table '" + re.escape(missing) + r"' not found; make one with `ship_lrm wake "
               r"--preset default --out " + re.escape(missing) + "`")
        if os.path.exists(missing):
            sys.exit("FAILED: a table was created where none was asked for")
    out = launch([f"wake_file:={table}", "N:=3"])
    expect(out, "invalid parameter", r"LrmSolver: parameter /approach/N must lie in \[16, 512\], got 3")
    out = launch([f"wake_file:={table}", "N:=16", "reach:=0.5"])
    expect(out, "invalid parameter", r"parameter /approach/reach must lie in \[1, 8\] \(domain edge / 4R\), got 0\.5")
    out = launch([f"wake_file:={table}", "N:=16", "faces:=nope"])
    expect(out, "invalid face set-up", r"parameters /approach/faces, .*: unknown face set-up 'nope' \(thesis, open-sides")
    # a private parameter of another type is refused, not replaced by its default (roslaunch makes
    # the string "abc" of it; ros::NodeHandle::param used to fall back to 30 s silently)
    out = launch([f"wake_file:={table}", "N:=16", "lrm_timeout:=abc"])
    expect(out, "private parameter of the wrong type", r"FlightModel: parameter /flight_model/lrm_timeout must be a number, got 'abc'")
    # "1e9" comes as text from roslaunch and is read as the number it is: refused for its size, not its type
    out = launch([f"wake_file:={table}", "N:=16", "reach:=1e9"])
    expect(out, "a number roslaunch leaves as text", r"parameter /approach/reach must lie in \[1, 8\] \(domain edge / 4R\), got 1000000000")
    print("PASSED")


if __name__ == "__main__":
    main()
