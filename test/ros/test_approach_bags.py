#!/usr/bin/python3
"""recorded-bag check: two simulated-time runs of approach.launch with record:=true, each on its
own ROS master, give bags whose rotor loads are identical in every field and every sample; the analysis
script turns such a bag into its plots, its summary and the loads as CSV, matching the bag. The bags
also hold every request of the flight model to the LRM solver and every answer from t = 0
(record_requests:=true; the solver and the flight model wait for the recorder): when the loads differ,
the failure names the first request and the first answer that differ, so that it tells which side
parted first.

    test_approach_bags.py TINY_TABLE.h5 WORK_DIR    (run through the workspace's devel/env.sh)"""
import csv
import os
import shutil
import socket
import subprocess
import sys

import rosbag

N, DURATION, STARTUP = "16", 1.0, 0.2
FIELDS = ["time", "thrust", "ct", "cmx", "cmy", "main_power", "distance", "height_above_deck", "speed", "inflow_model", "fallback"]


def free_port():
    with socket.socket() as s:
        s.bind(("localhost", 0))
        return s.getsockname()[1]


def run_launch(table, bag, log):
    port = free_port()
    env = dict(os.environ, ROS_MASTER_URI=f"http://localhost:{port}")
    args = ["roslaunch", "-p", str(port), "ship_lrm", "approach.launch", f"wake_file:={table}", "backend:=cpu", f"N:={N}",
            f"duration:={DURATION}", f"startup:={STARTUP}", "start_distance:=10", "height:=5", "record:=true", "record_requests:=true", f"bag:={bag}"]
    with open(log, "w") as f:
        rc = subprocess.run(args, env=env, stdout=f, stderr=subprocess.STDOUT, timeout=300).returncode
    if rc != 0 or not os.path.isfile(bag):
        sys.exit(f"FAILED: {' '.join(args)} exited with {rc} (log {log})")


def loads(bag):
    with rosbag.Bag(bag) as b:
        return [tuple(getattr(m, f) for f in FIELDS) for _, m, _ in b.read_messages(topics=["/rotor/loads"])]


def flat(m):
    """Every number of a message but its header, in field order (vectors and arrays expanded)."""
    if isinstance(m, (int, float)):
        return (m,)
    if isinstance(m, (list, tuple)):
        return tuple(v for x in m for v in flat(x))
    return tuple(v for f in m.__slots__ if f != "header" for v in flat(getattr(m, f)))


def requests(bag):
    """The flight model's requests to the LRM solver: sequence, time and every other number of each."""
    with rosbag.Bag(bag) as b:
        return [(m.sequence, m.time) + flat(m) for _, m, _ in b.read_messages(topics=["/rotor/forces"])]


def first_difference(a, b, what):
    """Where two recorded series of (sequence, time, ...) part, in words. They are matched by sequence
    number (the first of a sequence's copies), since a recorder may have missed some."""
    da, db = {}, {}
    for x in a:
        da.setdefault(x[0], x)
    for y in b:
        db.setdefault(y[0], y)
    common = sorted(set(da) & set(db))
    counts = f"{len(a)} and {len(b)} {what} recorded, {len(common)} sequence numbers in both"
    k = next((k for k in common if da[k] != db[k]), None)
    if k is None:
        return f"{counts}: they agree"
    x, y = da[k], db[k]
    i = next(i for i, (u, v) in enumerate(zip(x, y)) if u != v) if len(x) == len(y) else None
    where = f"value {i}: {x[i]!r} against {y[i]!r}" if i is not None else f"{len(x)} against {len(y)} values"
    return f"{counts}; first differing {what[:-1]}: sequence {k} (t = {x[1]:g} / {y[1]:g} s), {where}"


def inflows(bag):
    """The LRM solver's answers: sequence, time and the 9 inflow components of each."""
    with rosbag.Bag(bag) as b:
        return [(m.sequence, m.time) + tuple(getattr(getattr(m, v), a) for v in ("mean", "sine", "cosine") for a in "xyz")
                for _, m, _ in b.read_messages(topics=["/rotor/inflow"])]


def spans(numbers):
    """Sorted sequence numbers as runs, "3-7, 12" (where in the run a recorder lost messages)."""
    runs = []
    for n in numbers:
        if runs and n == runs[-1][1] + 1:
            runs[-1][1] = n
        else:
            runs.append([n, n])
    return ", ".join(f"{a}" if a == b else f"{a}-{b}" for a, b in runs) or "none"


def main():
    table, work = sys.argv[1], sys.argv[2]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    bags = [os.path.join(work, f"run{i}.bag") for i in (1, 2)]
    for i, bag in enumerate(bags):
        run_launch(table, bag, os.path.join(work, f"run{i + 1}.log"))
    a, b = loads(bags[0]), loads(bags[1])
    failures = []
    expected = int(round(DURATION / 0.01)) + 1  # t = 0, 0.01, ..., 1.0: the recorder saw every sample
    if len(a) != expected or len(b) != expected:
        failures.append(f"{len(a)} and {len(b)} loads in the bags, expected {expected} each")
    diff = [(x[0], f) for x, y in zip(a, b) for f, u, v in zip(FIELDS, x, y) if u != v]
    if diff:
        failures.append(f"{len(diff)} fields differ between the runs, first {diff[0][1]} at t = {diff[0][0]:g} s")
        # which side parted first: the flight model's requests or the LRM solver's answers (the bags hold them all)
        failures.append(first_difference(requests(bags[0]), requests(bags[1]), "requests"))
        failures.append(first_difference(inflows(bags[0]), inflows(bags[1]), "answers"))
    for bag in bags:  # every request and every answer from t = 0 (the solver and the flight model wait for the recorder)
        sent, answered = [r[0] for r in requests(bag)], {x[0] for x in inflows(bag)}
        if not sent or sent != list(range(len(sent))) or answered != set(sent):
            failures.append(f"{os.path.basename(bag)} misses requests or answers: {len(sent)} requests "
                            f"(sequence numbers {'' if sent == list(range(len(sent))) else 'not '}0, 1, ...), "
                            f"answers to {len(answered & set(sent))} of them; unanswered: {spans(sorted(set(sent) - answered))}")
    if any(x[-2] != "lrm" or x[-1] for x in a):
        failures.append("not every load came from the LRM")

    out = os.path.join(work, "analysis")
    here = os.path.dirname(os.path.abspath(__file__))
    script = os.path.join(here, "..", "..", "scripts", "analyze_approach.py")
    subprocess.run(["/usr/bin/python3", script, bags[0], "--out", out, "--startup", str(STARTUP)], check=True)
    for name in ["approach.png", "approach_wavelets.png", "approach_summary.csv", "approach_loads.csv"]:
        p = os.path.join(out, name)
        if not (os.path.isfile(p) and os.path.getsize(p) > 0):
            failures.append(f"the analysis did not write {name}")
    with open(os.path.join(out, "approach_loads.csv")) as f:
        rows = list(csv.DictReader(f))
    if [float(r["CT"]) for r in rows] != [x[2] for x in a]:
        failures.append("approach_loads.csv does not hold the bag's C_T exactly")
    with open(os.path.join(out, "approach_summary.csv")) as f:
        summary = list(csv.DictReader(f))
    k0 = next(i for i, x in enumerate(a) if x[0] >= STARTUP)
    ct = [r for r in summary if r["coefficient"] == "CT" and r["phase"] == "start-up"]
    if not ct or abs(float(ct[0]["value_at_startup"]) - a[k0][2]) > 1e-6 * abs(a[k0][2]):
        failures.append("the summary's C_T at the start-up is not the bag's")
    if failures:
        for i in (1, 2):  # the runs' warnings (a solver that gave up waiting for the recorder says so)
            with open(os.path.join(work, f"run{i}.log"), errors="replace") as f:
                warnings = [line.strip() for line in f if "WARN" in line or "ERROR" in line]
            print(f"run{i}.log: {len(warnings)} warnings" + "".join(f"\n  {w[:300]}" for w in warnings[:8]))
        sys.exit("FAILED: " + "; ".join(failures))
    print(f"two runs: {len(a)} identical loads; analysis written to {out}")


if __name__ == "__main__":
    main()
