#!/usr/bin/python3
"""rviz check: rviz opens rviz/lrm.rviz headless (Xvfb, software OpenGL) while a short real-time
approach runs on a tiny table, and renders a non-empty image: the screenshot (kept at OUT.png) must show
the scene's coloured content (the slice's rainbow, the ship, the arrows), not only the empty
background and the grey panels.

    test_rviz_screenshot.py TINY_TABLE.h5 OUT.png    (run through the workspace's devel/env.sh)"""
import os
import shutil
import signal
import socket
import subprocess
import sys
import time

import rosgraph


def free_port():
    with socket.socket() as s:
        s.bind(("localhost", 0))
        return s.getsockname()[1]


def free_display():
    for n in range(90, 200):
        if not os.path.exists(f"/tmp/.X{n}-lock") and not os.path.exists(f"/tmp/.X11-unix/X{n}"):
            return f":{n}"
    sys.exit("FAILED: no free X display number")


def saturated_fraction(png):
    """Fraction of pixels with a strongly coloured value (max - min channel > 80): the rviz panels and
    the empty background are greys, the scene's slice, ship shading and arrows are not."""
    out = subprocess.run(["convert", png, "-resize", "320x200!", "-depth", "8", "rgb:-"], capture_output=True, check=True).stdout
    n = len(out) // 3
    coloured = sum(1 for i in range(n) if max(out[3 * i:3 * i + 3]) - min(out[3 * i:3 * i + 3]) > 80)
    return coloured / max(n, 1)


def main():
    table, shot = sys.argv[1], sys.argv[2]
    for tool in ["Xvfb", "rviz", "import", "convert"]:
        if not shutil.which(tool):
            sys.exit(f"FAILED: {tool} is not installed (scripts/setup.sh installs xvfb, rviz, imagemagick)")
    port, display = free_port(), free_display()
    env = dict(os.environ, ROS_MASTER_URI=f"http://localhost:{port}", DISPLAY=display, LIBGL_ALWAYS_SOFTWARE="1")
    procs = []

    def start(args, **kw):
        p = subprocess.Popen(args, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True, **kw)
        procs.append(p)
        return p

    try:
        start(["Xvfb", display, "-screen", "0", "1280x800x24", "+extension", "GLX"])
        start(["roscore", "-p", str(port)])
        master = rosgraph.Master("/test_rviz", master_uri=env["ROS_MASTER_URI"])
        for _ in range(150):
            try:
                master.getPid()
                break
            except Exception:
                time.sleep(0.2)
        here = os.path.dirname(os.path.abspath(__file__))
        config = os.path.join(here, "..", "..", "rviz", "lrm.rviz")
        start(["rviz", "-d", config])
        # rviz is up when it subscribes to the slice
        deadline = time.time() + 120
        while time.time() < deadline:
            try:
                subs = dict(master.getSystemState()[1])
                if "/lrm/slice" in subs:
                    break
            except Exception:
                pass
            time.sleep(0.5)
        else:
            sys.exit("FAILED: rviz did not subscribe to /lrm/slice within 120 s")
        run = start(["roslaunch", "-p", str(port), "ship_lrm", "approach.launch", f"wake_file:={table}", "backend:=cpu", "N:=16",
                     "duration:=1.9", "startup:=0.1", "start_distance:=20", "height:=5", "realtime:=true",
                     "shutdown_when_done:=false"])
        # the run takes 1.9 s of wall time after start-up; rviz keeps the last slice and markers
        time.sleep(12)
        if run.poll() is not None:
            sys.exit(f"FAILED: the approach launch ended early ({run.returncode})")
        subprocess.run(["import", "-window", "root", shot], env=env, check=True, timeout=60)
        frac = saturated_fraction(shot)
        print(f"screenshot {shot}: {100 * frac:.1f} % coloured pixels")
        if frac < 0.01:
            sys.exit(f"FAILED: the rviz image is empty ({100 * frac:.2f} % coloured pixels)")
    finally:
        for p in reversed(procs):
            try:
                os.killpg(p.pid, signal.SIGINT)
            except ProcessLookupError:
                pass
        for p in reversed(procs):
            try:
                p.wait(timeout=15)
            except subprocess.TimeoutExpired:
                os.killpg(p.pid, signal.SIGKILL)


if __name__ == "__main__":
    main()
