#!/usr/bin/env python3
"""Independent check of an rtaware recording with the Python MCAP readers.

Usage: check_recording.py RUN.mcap RUN_DIR

Opens the file with the ``mcap`` package (CRCs of chunks and data section validated), decodes
every CDR message with ``mcap-ros2-support`` (from the ros2msg definitions in the file; the
JSON inside ``rtaware_msgs/msg/StateJson`` messages with ``json``), then compares:

- ``/ground_truth`` poses with the rows of RUN_DIR/trajectory.csv (same samples, same order);
- ``/odom`` pose and twist with the run's own odometry values on ``/rtaware/state/odometry``
  and the ground truth nearest in time;
- ``/cmd_vel`` with ``/rtaware/state/motor``;
- ``/scan``: beam count from the angles, ranges within [0, range_max], range_max as recorded;
- the summary's message count with the messages read, and report.json's recording section.

Prints one line per check and exits 1 on the first failure. Needs: mcap, mcap-ros2-support
(see .ci/python-peers.txt).
"""
import bisect
import csv
import json
import math
import sys
from collections import Counter

from mcap.reader import make_reader
from mcap_ros2.decoder import DecoderFactory


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def check(condition, message):
    if not condition:
        fail(message)


def yaw(q):
    return math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))


def main(mcap_path, run_dir):
    by_topic = {}
    decoded = 0
    with open(mcap_path, "rb") as f:
        reader = make_reader(f, decoder_factories=[DecoderFactory()], validate_crcs=True)
        summary = reader.get_summary()
        count = 0
        for schema, channel, message in reader.iter_messages(log_time_order=False):
            count += 1
            if channel.message_encoding == "cdr":
                continue
            check(channel.message_encoding == "json", "unexpected encoding " + channel.message_encoding)
            by_topic.setdefault(channel.topic, []).append((message.log_time, json.loads(message.data)))
        f.seek(0)
        reader = make_reader(f, decoder_factories=[DecoderFactory()], validate_crcs=True)
        cdr_topics = [c.topic for c in summary.channels.values() if c.message_encoding == "cdr"]
        for schema, channel, message, value in reader.iter_decoded_messages(topics=cdr_topics, log_time_order=False):
            decoded += 1
            if schema.name == "rtaware_msgs/msg/StateJson":
                value = json.loads(value.json)
            by_topic.setdefault(channel.topic, []).append((message.log_time, value))
    check(count == summary.statistics.message_count, "summary says %d messages, read %d"
          % (summary.statistics.message_count, count))
    print("ok: %d messages, CRCs valid, %d CDR messages decoded" % (count, decoded))

    with open(run_dir + "/report.json") as f:
        report = json.load(f)
    rec = report["recording"]
    check(rec["messages"] == count, "report.json recording.messages %s != %d" % (rec["messages"], count))
    print("ok: report.json recording section matches (%d messages, %d dropped)" % (count, rec["dropped"]))

    with open(run_dir + "/trajectory.csv") as f:
        rows = [(float(r["t_s"]), float(r["x_m"]), float(r["y_m"]), float(r["yaw_rad"])) for r in csv.DictReader(f)]
    truth = by_topic.get("/ground_truth", [])
    check(len(truth) == len(rows), "%d ground-truth messages, %d trajectory rows" % (len(truth), len(rows)))
    for (t, msg), row in zip(truth, rows):
        p = msg.pose.position
        check(abs(p.x - row[1]) <= 6e-5 and abs(p.y - row[2]) <= 6e-5 and abs(yaw(msg.pose.orientation) - row[3]) <= 6e-5,
              "ground truth %s,%s differs from trajectory row %s" % (p.x, p.y, row))
    print("ok: %d /ground_truth poses equal trajectory.csv" % len(truth))

    def paired(topic, state_topic):
        a, b = by_topic.get(topic, []), by_topic.get(state_topic, [])
        check(len(a) > 0 and len(a) == len(b), "%s: %d messages, %s: %d" % (topic, len(a), state_topic, len(b)))
        return zip(a, b)

    truth_times = [t for t, _ in truth]
    n = 0
    for (t, odom), (t2, state) in paired("/odom", "/rtaware/state/odometry"):
        check(t == t2, "odometry log times differ")
        p = odom.pose.pose.position
        check(p.x == state["xM"] and p.y == state["yM"], "odom pose %s,%s != state %s" % (p.x, p.y, state))
        check(abs(yaw(odom.pose.pose.orientation) - state["yawRad"]) < 1e-9, "odom yaw differs: %s" % state)
        tw = odom.twist.twist
        check(tw.linear.x == state["vxMps"] and tw.angular.z == state["omegaRadPerSec"], "odom twist differs")
        n += 1
    print("ok: %d /odom messages: pose and twist equal the recorded odometry values" % n)
    if truth:
        worst = 0.0
        for t, odom in by_topic["/odom"]:
            i = min(max(bisect.bisect_left(truth_times, t), 0), len(truth) - 1)
            g = truth[i][1].pose.position
            p = odom.pose.pose.position
            worst = max(worst, math.hypot(g.x - p.x, g.y - p.y))
        check(worst < 0.5, "odometry strays %.3f m from the nearest ground truth" % worst)
        print("ok: /odom within %.3f m of the ground truth nearest in time" % worst)

    n = 0
    for (t, cmd), (t2, state) in paired("/cmd_vel", "/rtaware/state/motor"):
        check(cmd.linear.x == state["vxMps"] and cmd.angular.z == state["omegaRadPerSec"],
              "cmd_vel %s,%s != motor %s" % (cmd.linear.x, cmd.angular.z, state))
        n += 1
    print("ok: %d /cmd_vel twists equal the motor commands" % n)

    n = 0
    for (t, scan), (t2, state) in paired("/scan", "/rtaware/state/laser"):
        beams = len(scan.ranges)
        check(beams > 1, "scan without beams")
        expected = round((scan.angle_max - scan.angle_min) / scan.angle_increment) + 1
        check(expected == beams, "scan of %d beams, angles say %d" % (beams, expected))
        check(all(0 <= r <= scan.range_max + 1e-6 for r in scan.ranges), "range outside [0, range_max]")
        check(abs(scan.range_max - state["maxRangeM"]) < 1e-6, "range_max differs")
        check(abs(scan.angle_min - state["minAngleRad"]) < 1e-6, "angle_min differs")
        n += 1
    print("ok: %d /scan messages: beam counts, ranges and limits consistent" % n)

    topics = Counter(c.topic for c in summary.channels.values())
    for t in ("/map", "/plan"):
        check(t in topics, "no %s channel" % t)
    check(any(t.startswith("/rtaware/timing/") for t in topics), "no timing channel")
    print("ok: channels " + ", ".join(sorted(topics)))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        print(__doc__)
        sys.exit(2)
    main(sys.argv[1], sys.argv[2])
