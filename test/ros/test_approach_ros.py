#!/usr/bin/python3
"""approach launch check (rostest, launched by approach.test, by free_flight.test with
~free_flight true, and by wake_server.test, whose solver gets the table from the wake server): the approach in simulated time on a tiny table publishes its topics and every tf
frame; its loads are finite and identical, sample by sample, to those of the ROS-free batch tool
`ship_lrm approach` for the same configuration (held on the path, or flying freely after the start-up:
then the LRM domain's pose travels in every request, and the helicopter leaves the path). The `trim`
service answers with the trim the flight model published on pilot/trim, and refuses a bad request."""
import csv
import math
import os
import subprocess
import tempfile
import time
import unittest

import rospy
import roslib.packages
import rostest
import tf2_ros
from diagnostic_msgs.msg import DiagnosticArray
from geometry_msgs.msg import TwistStamped
from nav_msgs.msg import Odometry
from sensor_msgs import point_cloud2
from sensor_msgs.msg import PointCloud2

from ship_lrm.msg import PilotControls, RotorLoads, WakeInfo
from ship_lrm.srv import Trim

DURATION = 1.0
FRAMES = ["world", "world_ned", "base_link", "base_link_frd", "main_rotor", "lrm_domain", "ship", "ship_frd"]


class ApproachLaunch(unittest.TestCase):
    def test_topics_frames_and_loads_as_the_batch_tool(self):
        loads, seen = [], {}
        # tf and the counted topics connected before the loads' subscription lets the flight model start: the run is
        # over in well under a second of wall clock, and a listener that connected after it would hold no
        # frames at all (simulated time then stands still, so tf's own timeouts would never end)
        buffer = tf2_ros.Buffer(cache_time=rospy.Duration(100))
        listener = tf2_ros.TransformListener(buffer)

        def count(name):
            return lambda msg: seen.__setitem__(name, seen.get(name, 0) + 1)

        slices = []  # the last lrm/slice

        def keep(m):
            slices[:] = [m]

        rospy.Subscriber("/lrm/slice", PointCloud2, keep)
        sources = set()  # where the LRM solver says its wake table comes from (diagnostics)
        rospy.Subscriber("/diagnostics", DiagnosticArray, lambda a: sources.update(
            v.value for s in a.status if "LRM solver" in s.name for v in s.values if v.key == "wake table from"))
        jobs = {}  # the LRM solver's job times (diagnostics)
        rospy.Subscriber("/diagnostics", DiagnosticArray, lambda a: jobs.update(
            {v.key: v.value for s in a.status if "LRM solver" in s.name for v in s.values if v.key.startswith("job (ms)")}))
        counted = [rospy.Subscriber(topic, kind, count(topic))
                   for topic, kind in [("/odom", Odometry), ("/ship/twist", TwistStamped), ("/lrm/slice", PointCloud2),
                                       ("/wake/info", WakeInfo), ("/diagnostics", DiagnosticArray)]]
        deadline = time.time() + 60
        while time.time() < deadline and not (listener.tf_sub.get_num_connections() and counted[0].get_num_connections()):
            time.sleep(0.05)
        self.assertGreater(listener.tf_sub.get_num_connections(), 0, "no /tf publisher within 60 s")
        self.assertGreater(counted[0].get_num_connections(), 0, "no /odom publisher within 60 s")
        rospy.Subscriber("/rotor/loads", RotorLoads, loads.append)  # last: the flight model starts with it
        deadline = time.time() + 240
        while time.time() < deadline and not (loads and loads[-1].time >= DURATION - 1e-3):
            time.sleep(0.1)
        self.assertTrue(loads, "no rotor/loads within 240 s")
        self.assertGreaterEqual(loads[-1].time, DURATION - 1e-3, "the approach did not reach its end")
        time.sleep(1.0)  # let the ship's timer and the last diagnostics go out

        # every load finite, from the LRM, one every 0.01 s (the flight model waits for this subscriber)
        for m in loads:
            for v in (m.thrust, m.ct, m.cmx, m.cmy, m.main_power):
                self.assertTrue(math.isfinite(v), "non-finite load at t = %g" % m.time)
            self.assertEqual(m.inflow_model, "lrm")
            self.assertFalse(m.fallback)
        self.assertEqual(len(loads), int(round(DURATION / 0.01)) + 1)  # t = 0, 0.01, ..., 1.0
        for topic in ["/odom", "/ship/twist", "/lrm/slice", "/wake/info", "/diagnostics"]:
            self.assertGreater(seen.get(topic, 0), 0, "nothing on " + topic)
        self.assertGreaterEqual(seen["/odom"], int(DURATION / 0.02) - 2)  # 50 Hz in simulated time
        # the slice carries the table's air beside the LRM's, and their difference
        names = ["u", "v", "w", "wall", "table_u", "table_v", "table_w", "difference"]
        self.assertTrue(slices, "no lrm/slice kept")
        points = list(point_cloud2.read_points(slices[-1], field_names=names))
        self.assertGreater(len(points), 100)
        for u, v, w, wall, tu, tv, tw, d in points:
            self.assertTrue(all(math.isfinite(a) for a in (tu, tv, tw, d)))
            self.assertAlmostEqual(d, math.sqrt((u - tu) ** 2 + (v - tv) ** 2 + (w - tw) ** 2), delta=1e-3 * (1 + d))
        wind = math.sqrt(sum(a * a for a in points[0][4:7]))
        self.assertGreater(wind, 1.0)  # the tiny table's air relative to the domain: wind and path speed
        self.assertEqual(sources, {rospy.get_param("~wake_source", "file")})
        self.assertGreater(float(jobs.get("job (ms), p99 of the last 1000", 0)), 0.0)
        self.assertLessEqual(float(jobs["job (ms), p50 of the last 1000"]), float(jobs["job (ms), p99 of the last 1000"]))
        for frame in FRAMES[1:]:  # no timeout argument: it would wait in the stopped simulated time
            self.assertTrue(buffer.can_transform("world", frame, rospy.Time(0)), "no tf from world to " + frame)

        # the batch tool, same configuration: identical loads at every shared time
        exe = roslib.packages.find_node("ship_lrm", "ship_lrm")
        self.assertTrue(exe, "the ship_lrm program is not in the catkin workspace")
        out = tempfile.mkdtemp(prefix="ship_lrm_rostest_")
        free_flight = rospy.get_param("~free_flight", False)
        subprocess.check_call([exe[0], "approach", "--wake", rospy.get_param("~wake_file"), "--backend", "cpu", "--N", "16",
                               "--duration", str(DURATION), "--startup", "0.1", "--start-distance", "10", "--height", "5",
                               "--output-interval", "0.01", "--no-plot", "--out", out] + (["--free-flight"] if free_flight else []),
                              stdout=subprocess.DEVNULL)
        with open(os.path.join(out, "approach.csv")) as f:
            rows = list(csv.DictReader(f))
        batch = {round(float(r["time_s"]), 6): r for r in rows}
        compared = 0
        for m in loads:
            r = batch.get(round(m.time, 6))
            if r is None:
                continue
            self.assertEqual(m.ct, float(r["CT"]), "C_T differs at t = %g" % m.time)
            self.assertEqual(m.cmx, float(r["CMx"]), "C_Mx differs at t = %g" % m.time)
            self.assertEqual(m.cmy, float(r["CMy"]), "C_My differs at t = %g" % m.time)
            compared += 1
        self.assertEqual(compared, len(loads), "the ROS and batch sample times do not match")
        # held: on the path, 5 m above the deck; free: it has left the path (the Pitt-Peters trim's
        # controls do not trim the LRM's inflow exactly), the same way in both
        end = batch[round(loads[-1].time, 6)]
        self.assertAlmostEqual(loads[-1].height_above_deck, float(end["height_above_deck_m"]), places=9)
        if free_flight:
            self.assertGreater(abs(loads[-1].height_above_deck - 5.0), 0.02)
        else:
            self.assertAlmostEqual(loads[-1].height_above_deck, 5.0, places=6)

    def test_trim_service(self):
        published = rospy.wait_for_message("/pilot/trim", PilotControls, timeout=120)
        rospy.wait_for_service("/trim", timeout=60)
        trim = rospy.ServiceProxy("/trim", Trim)
        answer = trim(speed=25.58, climb_angle=0.0)  # the approach's trim (20.58 m/s wind + 5 m/s)
        self.assertTrue(answer.converged, answer.message)
        self.assertAlmostEqual(answer.collective, published.collective, delta=1e-4)  # % (the table stores the wind in float)
        self.assertAlmostEqual(answer.longitudinal, published.longitudinal, delta=1e-4)
        self.assertGreater(answer.main_power, 0)
        bad = trim(speed=-1.0, climb_angle=0.0)
        self.assertFalse(bad.converged)
        self.assertIn("speed", bad.message)


if __name__ == "__main__":
    rospy.init_node("test_approach_ros")
    rostest.rosrun("ship_lrm", "approach_ros", ApproachLaunch)
