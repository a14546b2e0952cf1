#!/usr/bin/python3
"""Real-time benchmark of the ROS layer (real-time target), run by launch/bench_realtime.launch:
moves the stick (sensor_msgs/Joy on /joy, through the Scenario nodelet) in small collective steps at
`rate` Hz while the approach runs paced to the wall clock, and measures for every input the time from
its stamp to the arrival here of the first ship_lrm/RotorLoads that carries it (pilot_stamp): pilot
input to published loads, both hops included. At the end of the run writes a JSON summary to `~out`
(and prints it): latencies (p50, p99, max), the FlightModel's deadline misses and the LrmSolver's job
times (their diagnostics), the share of loads on the Pitt-Peters fallback per 5 s (where the misses
fall), and the run's length. Wall-clock stamps: needs realtime:=true."""
import json
import math
import threading
import time

import rospy
from diagnostic_msgs.msg import DiagnosticArray
from sensor_msgs.msg import Joy
from std_msgs.msg import String

from ship_lrm.msg import RotorLoads


def percentile(xs, q):
    xs = sorted(xs)
    if not xs:
        return float("nan")
    k = min(len(xs) - 1, max(0, int(math.ceil(q / 100.0 * len(xs))) - 1))
    return xs[k]


def main():
    rospy.init_node("bench_pilot_latency")
    out = rospy.get_param("~out", "")
    rate = float(rospy.get_param("~rate", 20.0))
    amplitude = float(rospy.get_param("~amplitude", 0.1))  # stick deflection (collective: gain 20 % -> 2 %)
    lock = threading.Lock()
    sent, latency, flight = {}, [], {}
    windows = {}  # 5 s of simulated time -> [loads, of them on Pitt-Peters (fallback)]
    done = threading.Event()

    def on_loads(m):
        now = time.time()
        key = m.pilot_stamp.to_nsec()
        with lock:
            w = windows.setdefault(int(m.time // 5.0) * 5, [0, 0])
            w[0] += 1
            w[1] += int(m.fallback)
            if key in sent and key not in flight:
                flight[key] = now
                latency.append(now - sent[key])

    diag, lrm_diag = {}, {}

    def on_diag(a):
        for s in a.status:
            if s.name.endswith("flight model"):
                diag.update({v.key: v.value for v in s.values})
                diag["level"] = int(s.level)
                diag["message"] = s.message
            if s.name.endswith("LRM solver"):  # its job times (the LBM work of each request)
                lrm_diag.update({v.key: v.value for v in s.values})

    rospy.Subscriber("/rotor/loads", RotorLoads, on_loads, queue_size=1000, tcp_nodelay=True)
    rospy.Subscriber("/diagnostics", DiagnosticArray, on_diag)
    rospy.Subscriber("/approach/status", String, lambda m: done.set())
    joy = rospy.Publisher("/joy", Joy, queue_size=10, tcp_nodelay=True)
    # the first loads mean the run is under way (trim published, Scenario connected)
    rospy.wait_for_message("/rotor/loads", RotorLoads, timeout=600)
    start = time.time()
    k = 0
    while not done.is_set() and not rospy.is_shutdown():
        m = Joy()
        m.header.stamp = rospy.Time.from_sec(time.time())
        m.axes = [0.0] * 8
        m.axes[1] = amplitude if k % 2 == 0 else -amplitude
        with lock:
            sent[m.header.stamp.to_nsec()] = m.header.stamp.to_sec()
        joy.publish(m)
        k += 1
        done.wait(1.0 / rate)
    time.sleep(0.5)
    with lock:
        lat_ms = [1e3 * x for x in latency]
        result = {
            "inputs_sent": len(sent),
            "inputs_seen_in_loads": len(lat_ms),
            "latency_ms_p50": percentile(lat_ms, 50),
            "latency_ms_p99": percentile(lat_ms, 99),
            "latency_ms_max": max(lat_ms) if lat_ms else float("nan"),
            "wall_seconds": time.time() - start,
            "flight_model_diagnostics": diag,
            "lrm_solver_diagnostics": lrm_diag,
            # where the misses fall: [window start s, loads, of them fallback] (loads sample the steps)
            "loads_fallback_per_5s": [[t, n, f] for t, (n, f) in sorted(windows.items())],
        }
    text = json.dumps(result, indent=2, sort_keys=True)
    print(text)
    if out:
        with open(out, "w") as f:
            f.write(text + "\n")


if __name__ == "__main__":
    main()
