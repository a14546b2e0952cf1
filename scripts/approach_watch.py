#!/usr/bin/python3
"""Ends an approach launch cleanly (required node of launch/approach.launch): waits for "done" or
"failed: <why>" on approach/status (published by the nodelets, see include/ship_lrm/ros/run_status.hpp)
and exits 0 or 1, so that roslaunch stops every node the normal way. ~linger (s, wall clock) after
"done" lets a recorder write the last messages of its queue before roslaunch stops it (a run of a
second could otherwise end before rosbag had opened its bag)."""
import sys
import time

import rospy
from std_msgs.msg import String


def main():
    rospy.init_node("approach_watch")
    outcome = []
    rospy.Subscriber("approach/status", String, lambda m: outcome.append(m.data))
    while not rospy.is_shutdown() and not outcome:
        time.sleep(0.05)  # wall clock: /clock may not run yet
    if not outcome:
        return 0
    if outcome[0] == "done":
        rospy.loginfo("approach_watch: the approach is done")
        time.sleep(max(0.0, float(rospy.get_param("~linger", 0.0))))
        return 0
    rospy.logfatal("approach_watch: %s", outcome[0])
    return 1


if __name__ == "__main__":
    sys.exit(main())
