#!/usr/bin/python3
"""fault check (rostest, launched by fault.test): SIGKILL the stand-alone LRM solver while the
approach runs in real time. After the kill (plus the link's timeout) every load must be Pitt-Peters'
(fallback), finite, and the run must reach its end ("done" on approach/status); the flight model's
diagnostics must report the loss at ERROR level; the nodelet manager must still be there."""
import math
import os
import signal
import time
import unittest
import xmlrpc.client

import rosgraph
import rosnode
import rospy
import rostest
from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus
from std_msgs.msg import String

from ship_lrm.msg import RotorLoads

DURATION = 1.9


class SolverKilled(unittest.TestCase):
    def test_flight_model_falls_back_to_pitt_peters(self):
        loads, errors, status = [], [], []
        rospy.Subscriber("/rotor/loads", RotorLoads, loads.append, queue_size=1000)
        rospy.Subscriber("/approach/status", String, lambda m: status.append(m.data))

        def on_diag(a):
            for s in a.status:
                if s.name.endswith("flight model") and s.level == DiagnosticStatus.ERROR:
                    errors.append(s.message)

        rospy.Subscriber("/diagnostics", DiagnosticArray, on_diag)
        deadline = time.time() + 120
        while time.time() < deadline and not any(m.time >= 0.3 and m.inflow_model == "lrm" for m in loads):
            time.sleep(0.01)
        self.assertTrue(any(m.inflow_model == "lrm" for m in loads), "the LRM never served before the kill")

        master = rosgraph.Master("/test_solver_killed")
        uri = rosnode.get_api_uri(master, "/lrm_solver")
        self.assertTrue(uri, "no /lrm_solver node")
        code, _, pid = xmlrpc.client.ServerProxy(uri).getPid("/test_solver_killed")
        self.assertEqual(code, 1)
        os.kill(pid, signal.SIGKILL)
        t_kill = loads[-1].time

        while time.time() < deadline and "done" not in status:
            time.sleep(0.05)
        self.assertIn("done", status, "the run did not reach its end after the solver was killed")
        time.sleep(0.5)
        after = [m for m in loads if m.time > t_kill + 0.3 + 0.05]  # lrm_timeout = 0.3 s of wall (= simulated) time
        self.assertGreater(len(after), 20, "too few loads after the kill")
        for m in after:
            self.assertTrue(m.fallback and m.inflow_model == "pitt_peters", "LRM load at t = %g after the kill" % m.time)
        for m in loads:
            self.assertTrue(math.isfinite(m.ct) and math.isfinite(m.cmx) and math.isfinite(m.cmy), "non-finite load at t = %g" % m.time)
        self.assertGreaterEqual(loads[-1].time, DURATION - 1e-3)
        self.assertTrue(any("Pitt-Peters" in e for e in errors), "no ERROR diagnostic naming the fallback: %s" % errors[:3])
        self.assertIn("/ship_lrm_manager", rosnode.get_node_names(), "the nodelet manager is gone")
        self.assertTrue(rosnode.rosnode_ping("/ship_lrm_manager", max_count=1), "the nodelet manager does not answer")


if __name__ == "__main__":
    rospy.init_node("test_solver_killed")
    rostest.rosrun("ship_lrm", "solver_killed", SolverKilled)
