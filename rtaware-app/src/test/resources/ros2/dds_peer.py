"""A stock ROS 2 node on the wire, written with Eclipse Cyclone DDS's Python binding (issue 29).

It speaks DDS as rmw_cyclonedds does: topics rt/<name>, the ROS 2 DDS type names
(sensor_msgs::msg::dds_::LaserScan_, ...), sensor-data QoS (best effort) for the scan and
reliable QoS for odometry and commands, on the loopback interface with multicast off and unicast
discovery on 127.0.0.1 (ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST). rtaware's tests run it against
`sim --ros2 --dds` and `run --ros2 --dds`; it is never part of the product.

  drive --domain D --seconds T --speed V
      Reads rt/scan and rt/odom, sends V m/s forward on rt/cmd_vel at 10 Hz for T seconds, then
      a zero Twist; prints one JSON line (what it decoded, how far odometry says the robot moved).

  diagnostics --domain D --seconds T
      Reads rt/diagnostics (diagnostic_msgs/msg/DiagnosticArray, what rtaware's exporter
      publishes) for T seconds; prints one JSON line: messages and the status names seen.

  statistics --domain D --seconds T
      Reads rt/statistics (statistics_msgs/msg/MetricsMessage, ROS 2's topic statistics, what
      rtaware's exporter publishes) for T seconds, checking each message as ROS 2 publishes them
      (data types 1 to 5 in order, finite or NaN, NaN exactly when the count is 0, a window of
      one second); prints one JSON line: messages, the metrics seen per source, the windows seen,
      and the first message of each source and metric as `ros2 topic echo` would show it.

  twist-on --domain D --topic NAME
      A robot that publishes its NAME topic (scan, say) with the wrong type: a zero Twist on
      rt/NAME at 10 Hz until stdin closes. Prints "ready" once its writer exists and, when stdin
      closes, one JSON line: the Twists written.

  relay --from A --to B [--restamp] [--nan-odom-after S]
      A Cyclone DDS robot made of the simulator on domain A: scans and odometry from A are
      written again on B (with --restamp, stamped with this machine's clock as a driver stamps
      acquisition time; otherwise unchanged), commands from B are written on A. Every command is
      checked to be finite. With --nan-odom-after S, odometry on B carries NaN positions after S
      seconds (the halting rule's test). Prints "ready" once its readers and writers exist and
      one JSON line when stdin closes.
"""

import argparse
import json
import math
import os
import sys
import threading
import time
from dataclasses import dataclass

LOOPBACK = ("<CycloneDDS><Domain Id=\"any\"><General><Interfaces><NetworkInterface name=\"lo\"/></Interfaces>"
            "<AllowMulticast>false</AllowMulticast></General><Discovery><ParticipantIndex>auto</ParticipantIndex>"
            "<MaxAutoParticipantIndex>32</MaxAutoParticipantIndex><Peers><Peer address=\"127.0.0.1\"/></Peers>"
            "</Discovery></Domain></CycloneDDS>")
# Read by Cyclone DDS when the first participant is created: this peer never leaves this machine.
os.environ["CYCLONEDDS_URI"] = LOOPBACK

from cyclonedds.core import Policy, Qos  # noqa: E402
from cyclonedds.domain import DomainParticipant  # noqa: E402
from cyclonedds.idl import IdlStruct  # noqa: E402
from cyclonedds.idl.types import array, byte, float32, float64, int32, sequence, uint8, uint32  # noqa: E402
from cyclonedds.pub import DataWriter  # noqa: E402
from cyclonedds.sub import DataReader  # noqa: E402
from cyclonedds.topic import Topic  # noqa: E402
from cyclonedds.util import duration  # noqa: E402


@dataclass
class Time(IdlStruct, typename="builtin_interfaces::msg::dds_::Time_"):
    sec: int32
    nanosec: uint32


@dataclass
class Header(IdlStruct, typename="std_msgs::msg::dds_::Header_"):
    stamp: Time
    frame_id: str


@dataclass
class LaserScan(IdlStruct, typename="sensor_msgs::msg::dds_::LaserScan_"):
    header: Header
    angle_min: float32
    angle_max: float32
    angle_increment: float32
    time_increment: float32
    scan_time: float32
    range_min: float32
    range_max: float32
    ranges: sequence[float32]
    intensities: sequence[float32]


@dataclass
class Point(IdlStruct, typename="geometry_msgs::msg::dds_::Point_"):
    x: float64
    y: float64
    z: float64


@dataclass
class Quaternion(IdlStruct, typename="geometry_msgs::msg::dds_::Quaternion_"):
    x: float64
    y: float64
    z: float64
    w: float64


@dataclass
class Pose(IdlStruct, typename="geometry_msgs::msg::dds_::Pose_"):
    position: Point
    orientation: Quaternion


@dataclass
class PoseWithCovariance(IdlStruct, typename="geometry_msgs::msg::dds_::PoseWithCovariance_"):
    pose: Pose
    covariance: array[float64, 36]


@dataclass
class Vector3(IdlStruct, typename="geometry_msgs::msg::dds_::Vector3_"):
    x: float64
    y: float64
    z: float64


@dataclass
class Twist(IdlStruct, typename="geometry_msgs::msg::dds_::Twist_"):
    linear: Vector3
    angular: Vector3


@dataclass
class TwistWithCovariance(IdlStruct, typename="geometry_msgs::msg::dds_::TwistWithCovariance_"):
    twist: Twist
    covariance: array[float64, 36]


@dataclass
class Odometry(IdlStruct, typename="nav_msgs::msg::dds_::Odometry_"):
    header: Header
    child_frame_id: str
    pose: PoseWithCovariance
    twist: TwistWithCovariance


@dataclass
class KeyValue(IdlStruct, typename="diagnostic_msgs::msg::dds_::KeyValue_"):
    key: str
    value: str


@dataclass
class DiagnosticStatus(IdlStruct, typename="diagnostic_msgs::msg::dds_::DiagnosticStatus_"):
    level: byte
    name: str
    message: str
    hardware_id: str
    values: sequence[KeyValue]


@dataclass
class DiagnosticArray(IdlStruct, typename="diagnostic_msgs::msg::dds_::DiagnosticArray_"):
    header: Header
    status: sequence[DiagnosticStatus]


# The ROS graph as rmw announces it on DDS (rmw_dds_common, Iron and later: 16-byte gids): every
# ROS 2 node's participant writes which readers and writers belong to which node on
@dataclass
class StatisticDataPoint(IdlStruct, typename="statistics_msgs::msg::dds_::StatisticDataPoint_"):
    data_type: uint8
    data: float64


@dataclass
class MetricsMessage(IdlStruct, typename="statistics_msgs::msg::dds_::MetricsMessage_"):
    measurement_source_name: str
    metrics_source: str
    unit: str
    window_start: Time
    window_stop: Time
    statistics: sequence[StatisticDataPoint]


# ros_discovery_info; tools and bridges read it to tell ROS 2 nodes from other DDS entities.
@dataclass
class Gid(IdlStruct, typename="rmw_dds_common::msg::dds_::Gid_"):
    data: array[uint8, 16]


@dataclass
class NodeEntitiesInfo(IdlStruct, typename="rmw_dds_common::msg::dds_::NodeEntitiesInfo_"):
    node_namespace: str
    node_name: str
    reader_gid_seq: sequence[Gid]
    writer_gid_seq: sequence[Gid]


@dataclass
class ParticipantEntitiesInfo(IdlStruct, typename="rmw_dds_common::msg::dds_::ParticipantEntitiesInfo_"):
    gid: Gid
    node_entities_info_seq: sequence[NodeEntitiesInfo]


# The QoS a ROS 2 driver uses: sensor data for the scan, the default profile for the rest; the
# plain CDR (XCDR1) representation ROS 2's DDS middlewares write.
XCDR1 = Policy.DataRepresentation(use_cdrv0_representation=True)
SENSOR_DATA = Qos(Policy.Reliability.BestEffort, Policy.Durability.Volatile, Policy.History.KeepLast(5), XCDR1)
DEFAULT = Qos(Policy.Reliability.Reliable(duration(milliseconds=100)), Policy.Durability.Volatile,
              Policy.History.KeepLast(10), XCDR1)


GRAPH = Qos(Policy.Reliability.Reliable(duration(milliseconds=100)), Policy.Durability.TransientLocal,
            Policy.History.KeepLast(1), XCDR1)


def gid(entity):
    return Gid(data=list(entity.guid.bytes))


class Node:
    """One ROS 2 node on one domain: its topics, readers and writers, announced on
    ros_discovery_info as rmw announces a node's entities."""

    def __init__(self, domain, name):
        self.participant = DomainParticipant(domain)
        self.name = name
        self.topics = {}
        self.readers = []
        self.writers = []
        self.graph = DataWriter(self.participant, Topic(self.participant, "ros_discovery_info", ParticipantEntitiesInfo),
                                qos=GRAPH)

    def topic(self, name, kind):
        if name not in self.topics:
            self.topics[name] = Topic(self.participant, "rt/" + name, kind)
        return self.topics[name]

    def reader(self, name, kind, qos):
        reader = DataReader(self.participant, self.topic(name, kind), qos=qos)
        self.readers.append(reader)
        self.announce()
        return reader

    def writer(self, name, kind, qos):
        writer = DataWriter(self.participant, self.topic(name, kind), qos=qos)
        self.writers.append(writer)
        self.announce()
        return writer

    def announce(self):
        node = NodeEntitiesInfo(node_namespace="/", node_name=self.name,
                                reader_gid_seq=[gid(r) for r in self.readers],
                                writer_gid_seq=[gid(w) for w in self.writers])
        self.graph.write(ParticipantEntitiesInfo(gid=gid(self.participant), node_entities_info_seq=[node]))


def twist(vx, wz):
    return Twist(linear=Vector3(vx, 0.0, 0.0), angular=Vector3(0.0, 0.0, wz))


def drive(args):
    node = Node(args.domain, "dds_peer_driver")
    scans = node.reader("scan", LaserScan, SENSOR_DATA)
    odoms = node.reader("odom", Odometry, DEFAULT)
    cmd = node.writer("cmd_vel", Twist, DEFAULT)
    seen = {"scans": 0, "odometry": 0, "commands": 0, "failures": []}
    first_pose = last_pose = None
    end = time.monotonic() + args.seconds
    next_command = 0.0
    while time.monotonic() < end:
        for scan in scans.take(N=16):
            if seen["scans"] == 0:
                seen["first_scan"] = {"beams": len(scan.ranges), "frame": scan.header.frame_id,
                                      "range_max": scan.range_max}
            seen["scans"] += 1
        for odom in odoms.take(N=16):
            p = odom.pose.pose.position
            if not all(math.isfinite(v) for v in (p.x, p.y)):
                seen["failures"].append("odometry with a non-finite position")
            if seen["odometry"] == 0:
                seen["first_odometry"] = {"frame": odom.header.frame_id, "child": odom.child_frame_id}
                first_pose = (p.x, p.y)
            last_pose = (p.x, p.y)
            seen["odometry"] += 1
        now = time.monotonic()
        if now >= next_command:
            cmd.write(twist(args.speed, 0.0))
            seen["commands"] += 1
            next_command = now + 0.1
        time.sleep(0.01)
    cmd.write(twist(0.0, 0.0))
    seen["moved_m"] = math.dist(first_pose, last_pose) if first_pose and last_pose else 0.0
    if seen["scans"] == 0:
        seen["failures"].append("no scan on rt/scan")
    if seen["odometry"] == 0:
        seen["failures"].append("no odometry on rt/odom")
    print(json.dumps(seen), flush=True)
    return 1 if seen["failures"] else 0


def diagnostics(args):
    node = Node(args.domain, "dds_peer_diagnostics")
    # best effort reads a reliable writer too
    arrays = node.reader("diagnostics", DiagnosticArray, SENSOR_DATA)
    seen = {"messages": 0, "names": [], "failures": []}
    end = time.monotonic() + args.seconds
    while time.monotonic() < end:
        for array_message in arrays.take(N=16):
            seen["messages"] += 1
            for status in array_message.status:
                if status.name not in seen["names"]:
                    seen["names"].append(status.name)
        time.sleep(0.01)
    if seen["messages"] == 0:
        seen["failures"].append("no DiagnosticArray on rt/diagnostics")
    print(json.dumps(seen), flush=True)
    return 1 if seen["failures"] else 0


def statistics(args):
    node = Node(args.domain, "dds_peer_statistics")
    # reliable as the publisher; a deep history, since a second's messages come all at once
    metrics = node.reader("statistics", MetricsMessage, Qos(Policy.Reliability.Reliable(duration(milliseconds=100)),
                                                           Policy.Durability.Volatile, Policy.History.KeepLast(1000),
                                                           XCDR1))
    seen = {"messages": 0, "sources": {}, "windows": 0, "first": {}, "failures": []}
    windows = set()
    arrivals = {}
    end = time.monotonic() + args.seconds
    while time.monotonic() < end:
        for m in metrics.take(N=64):
            seen["messages"] += 1
            arrivals.setdefault((m.measurement_source_name, m.metrics_source), []).append(time.monotonic())
            start = m.window_start.sec * 1_000_000_000 + m.window_start.nanosec
            stop = m.window_stop.sec * 1_000_000_000 + m.window_stop.nanosec
            windows.add(start)
            what = "%s %s" % (m.measurement_source_name, m.metrics_source)
            types = [p.data_type for p in m.statistics]
            values = [p.data for p in m.statistics]
            if types != [1, 2, 3, 4, 5]:
                seen["failures"].append("%s: data types %s" % (what, types))
            elif any(math.isinf(v) for v in values) or any(math.isnan(v) != (values[4] == 0) for v in values[:4]):
                seen["failures"].append("%s: values %s" % (what, values))
            if stop - start != 1_000_000_000:
                seen["failures"].append("%s: a window of %d ns" % (what, stop - start))
            sources = seen["sources"].setdefault(m.measurement_source_name, [])
            if m.metrics_source not in sources:
                sources.append(m.metrics_source)
                seen["first"][what] = {"unit": m.unit, "window_start": start, "window_stop": stop,
                                       "statistics": [{"data_type": t, "data": None if math.isnan(v) else v}
                                                      for t, v in zip(types, values)]}
        time.sleep(0.01)
    seen["windows"] = len(windows)
    # as `ros2 topic hz` reports a rate: messages after the first over the time since it
    rates = [(len(t) - 1) / (t[-1] - t[0]) for t in arrivals.values() if len(t) > 2]
    seen["rate_hz_per_source_and_metric"] = [min(rates), max(rates)] if rates else None
    if seen["messages"] == 0:
        seen["failures"].append("no MetricsMessage on rt/statistics")
    print(json.dumps(seen), flush=True)
    return 1 if seen["failures"] else 0


def twist_on(args):
    node = Node(args.domain, "dds_peer_wrong_type")
    out = node.writer(args.topic, Twist, SENSOR_DATA)
    stop = threading.Event()
    threading.Thread(target=lambda: (sys.stdin.read(), stop.set()), daemon=True).start()
    print("ready", flush=True)
    written = 0
    while not stop.wait(0.1):
        out.write(twist(0.0, 0.0))
        written += 1
    print(json.dumps({"twists": written}), flush=True)
    return 0


def now_stamp():
    ns = time.time_ns()
    return Time(sec=ns // 1_000_000_000, nanosec=ns % 1_000_000_000)


def relay(args):
    robot = Node(getattr(args, "from"), "dds_peer_relay")
    world = Node(args.to, "dds_peer_robot")
    scans_in = robot.reader("scan", LaserScan, SENSOR_DATA)
    odoms_in = robot.reader("odom", Odometry, DEFAULT)
    cmd_out = robot.writer("cmd_vel", Twist, DEFAULT)
    scans_out = world.writer("scan", LaserScan, SENSOR_DATA)
    odoms_out = world.writer("odom", Odometry, DEFAULT)
    cmd_in = world.reader("cmd_vel", Twist, DEFAULT)
    counts = {"scans": 0, "odometry": 0, "commands": 0, "nan_odometry": 0, "failures": []}
    last_command = None
    started = time.monotonic()
    stop = threading.Event()
    threading.Thread(target=lambda: (sys.stdin.read(), stop.set()), daemon=True).start()
    print("ready", flush=True)
    while not stop.is_set():
        for scan in scans_in.take(N=16):
            if args.restamp:
                scan.header.stamp = now_stamp()
            scans_out.write(scan)
            counts["scans"] += 1
        for odom in odoms_in.take(N=16):
            if args.restamp:
                odom.header.stamp = now_stamp()
            if args.nan_odom_after is not None and time.monotonic() - started > args.nan_odom_after:
                odom.pose.pose.position.x = float("nan")
                counts["nan_odometry"] += 1
            odoms_out.write(odom)
            counts["odometry"] += 1
        for command in cmd_in.take(N=16):
            values = (command.linear.x, command.linear.y, command.linear.z,
                      command.angular.x, command.angular.y, command.angular.z)
            if not all(math.isfinite(v) for v in values):
                counts["failures"].append("a command with a non-finite value: %r" % (values,))
            cmd_out.write(command)
            last_command = [command.linear.x, command.angular.z]
            counts["commands"] += 1
        time.sleep(0.002)
    counts["last_command"] = last_command
    print(json.dumps(counts), flush=True)
    return 1 if counts["failures"] else 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="mode", required=True)
    d = sub.add_parser("drive")
    d.add_argument("--domain", type=int, required=True)
    d.add_argument("--seconds", type=float, default=10.0)
    d.add_argument("--speed", type=float, default=0.2)
    g = sub.add_parser("diagnostics")
    g.add_argument("--domain", type=int, required=True)
    g.add_argument("--seconds", type=float, default=10.0)
    s = sub.add_parser("statistics")
    s.add_argument("--domain", type=int, required=True)
    s.add_argument("--seconds", type=float, default=10.0)
    t = sub.add_parser("twist-on")
    t.add_argument("--domain", type=int, required=True)
    t.add_argument("--topic", required=True)
    r = sub.add_parser("relay")
    r.add_argument("--from", type=int, required=True)
    r.add_argument("--to", type=int, required=True)
    r.add_argument("--restamp", action="store_true")
    r.add_argument("--nan-odom-after", type=float)
    args = parser.parse_args()
    sys.exit({"drive": drive, "diagnostics": diagnostics, "statistics": statistics, "twist-on": twist_on,
              "relay": relay}[args.mode](args))


if __name__ == "__main__":
    main()
