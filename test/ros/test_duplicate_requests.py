#!/usr/bin/python3
"""Requests delivered twice (rostest, launched by duplicate_requests.test). roscpp can link a topic
twice within one process (one nodelet advertising it while another subscribes on another thread), and
then delivers every message twice, back to back: a bag test once saw the LRM solver serve every request
of the flight model twice, its fluid running twice as far as the flight model's time. Here the test node
is the flight model: a reset, then ADVANCES advances of one flight step each, each published twice in a
row. Each copy must get an answer, the same one; the solver must count the copies as duplicates; and the
fluid's time must be the flight model's (the sum of the steps, to within one LBM step), not twice it."""
import math
import time
import unittest

import rospy
import rostest
from diagnostic_msgs.msg import DiagnosticArray
from geometry_msgs.msg import Vector3
from rosgraph_msgs.msg import Clock

from ship_lrm.msg import RotorForces, RotorInflow

ADVANCES = 16
DT = 0.00180352  # s, the Bo 105 model's flight step
THRUST = 24525.0  # N, along -z of the mr frame
ROTATION = [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0]


def request(kind, sequence, t, dt):
    """A request of the approach on the tiny table: the hub 5 m above the deck's height, 10 m behind
    the spot (the first request of approach.test), moving aft-to-fore at 5 m/s, a uniform thrust."""
    m = RotorForces()
    m.header.stamp = rospy.Time(1.0 + t)
    m.kind, m.sequence, m.time, m.dt = kind, sequence, t, dt
    m.table_time = 10.0 + t
    m.radius, m.rotor_speed, m.density = 4.91, 44.4, 1.1934
    m.hub_velocity = Vector3(25.57, 0.0, -0.77)
    m.aero_force = Vector3(0.0, 0.0, -THRUST)
    m.harmonics_cos = [Vector3(0.0, 0.0, -THRUST if k == 0 else 0.0) for k in range(10)]
    m.harmonics_sin = [Vector3() for _ in range(10)]
    m.pose_hub = Vector3(-22.753 + 5.0 * t, 0.0192, -6.4902)
    m.pose_rotation = ROTATION
    m.pose_hub_velocity = Vector3(5.0, 0.0, 0.0)
    return m


class DuplicateRequests(unittest.TestCase):
    def test_a_request_delivered_twice_is_served_once(self):
        answers, diag = [], {}
        rospy.Subscriber("/rotor/inflow", RotorInflow, answers.append, queue_size=1000)
        rospy.Subscriber("/diagnostics", DiagnosticArray, lambda a: diag.update(
            {v.key: v.value for s in a.status if "LRM solver" in s.name for v in s.values}))
        clock = rospy.Publisher("/clock", Clock, queue_size=10, latch=True)
        forces = rospy.Publisher("/rotor/forces", RotorForces, queue_size=100)
        clock.publish(Clock(clock=rospy.Time(1.0)))
        deadline = time.time() + 120
        while time.time() < deadline and forces.get_num_connections() == 0:
            time.sleep(0.05)
        self.assertGreater(forces.get_num_connections(), 0, "no LRM solver on /rotor/forces")
        time.sleep(0.5)  # the answers' connection

        def wait_for(sequence, count):
            until = time.time() + 60
            while time.time() < until and sum(a.sequence == sequence for a in answers) < count:
                time.sleep(0.005)
            got = [a for a in answers if a.sequence == sequence]
            self.assertEqual(len(got), count, f"{len(got)} answers to request {sequence}, expected {count}")
            return got

        forces.publish(request(RotorForces.RESET, 0, 0.0, 0.0))
        wait_for(0, 1)
        for k in range(1, ADVANCES + 1):
            m = request(RotorForces.ADVANCE, k, (k - 1) * DT, DT)
            forces.publish(m)
            forces.publish(m)  # the same message again, right behind it
            a, b = wait_for(k, 2)
            for v in ("mean", "sine", "cosine"):
                self.assertEqual(getattr(a, v), getattr(b, v), f"request {k}: the copy's answer differs")
            self.assertTrue(all(math.isfinite(x) for x in (a.mean.x, a.mean.y, a.mean.z)))
        # one more request (not repeated) after 5 s of ROS time: the diagnostics go out with it
        clock.publish(Clock(clock=rospy.Time(6.0)))
        time.sleep(0.3)
        diag.clear()
        forces.publish(request(RotorForces.ADVANCE, ADVANCES + 1, ADVANCES * DT, DT))
        wait_for(ADVANCES + 1, 1)
        until = time.time() + 30
        while time.time() < until and "fluid time (s)" not in diag:
            time.sleep(0.05)
        self.assertIn("fluid time (s)", diag, "no diagnostics of the LRM solver")
        self.assertEqual(int(diag["duplicate requests (answered again, not served)"]), ADVANCES)
        fluid, lbm_dt = float(diag["fluid time (s)"]), float(diag["LBM time step (s)"])
        flight = (ADVANCES + 1) * DT
        print(f"fluid time {fluid} s for {flight} s of flight steps (LBM step {lbm_dt} s)")
        self.assertLess(lbm_dt, flight / 3)  # so that serving the copies (2 x flight) would show
        self.assertLessEqual(abs(fluid - flight), lbm_dt, f"fluid time {fluid} s against the flight model's {flight} s")


if __name__ == "__main__":
    rospy.init_node("test_duplicate_requests")
    rostest.rosrun("ship_lrm", "duplicate_requests", DuplicateRequests)
