"""An independent ROS 2 peer for rtaware's tests: eclipse-zenoh, zenoh-ros2-sdk and rosbags.

  ros2_peer.py router --listen tcp/127.0.0.1:PORT
      A Zenoh router standing in for rmw_zenohd; prints "ready", runs until stdin closes.

  ros2_peer.py check --router tcp/127.0.0.1:PORT [--namespace /] [--timeout 60]
      Against rtaware's simulator served as a ROS 2 robot: lists the ROS graph through the
      liveliness tokens, decodes /scan and /odom with zenoh-ros2-sdk subscribers (types and
      RIHS01 hashes from rosbags' Jazzy store, nothing fetched from the internet), checks the
      REP 105 frames (/tf_static base_link -> laser, /tf odom -> base_link stamped and placed as
      an odometry sample, scans in laser, odometry in odom with child base_link), drives the
      robot with a zenoh-ros2-sdk /cmd_vel publisher and watches odometry move. Prints one JSON
      object with what it saw; exits 0 when every check passed, 1 otherwise (reasons in
      "failures").

  ros2_peer.py statistics --router tcp/127.0.0.1:PORT [--seconds 6]
      Subscribes /statistics (statistics_msgs/msg/MetricsMessage, ROS 2's topic statistics,
      what rtaware's exporter publishes) with zenoh-ros2-sdk for that long, checking each
      message as ROS 2 publishes them (data types 1 to 5 in order, finite or NaN, NaN exactly
      when the count is 0, a window of one second); prints one JSON object: messages, the metrics
      seen per source, the windows, and the first message of each source and metric as
      `ros2 topic echo` shows it; exits 1 if a check failed or nothing arrived.
"""

import argparse
import json
import math
import sys
import threading
import time


def router(listen):
    import zenoh

    conf = zenoh.Config()
    conf.insert_json5("mode", '"router"')
    conf.insert_json5("listen/endpoints", json.dumps([listen]))
    conf.insert_json5("scouting/multicast/enabled", "false")
    session = zenoh.open(conf)
    print("ready", flush=True)
    sys.stdin.read()
    session.close()
    return 0


def topic(namespace, name):
    return ("" if namespace == "/" else namespace) + "/" + name


def check(endpoint, namespace, timeout_s):
    from rosbags.typesys import Stores, get_typestore
    from zenoh_ros2_sdk import ROS2Publisher, ROS2Subscriber, ZenohSession, get_topic_info, get_topic_names_and_types

    host, port = endpoint[len("tcp/"):].rsplit(":", 1)
    port = int(port)
    jazzy = get_typestore(Stores.ROS2_JAZZY)
    session = ZenohSession.get_instance(host, port)
    # The SDK's own store starts empty: give it the Jazzy definitions of nested types too.
    session.store.register(dict(jazzy.fielddefs))

    def typed(name):
        return {"msg_type": name, "msg_definition": jazzy.generate_msgdef(name, ros_version=2)[0],
                "type_hash": jazzy.hash_rihs01(name), "router_ip": host, "router_port": port}

    lock = threading.Lock()
    scans, odoms, tfs, statics, clocks = [], [], [], [], []

    def on_scan(msg):
        with lock:
            scans.append({"beams": len(msg.ranges), "angle_min": float(msg.angle_min),
                          "angle_max": float(msg.angle_max), "range_max": float(msg.range_max),
                          "stamp_s": msg.header.stamp.sec + msg.header.stamp.nanosec * 1e-9,
                          "stamp_ns": msg.header.stamp.sec * 1_000_000_000 + msg.header.stamp.nanosec,
                          "frame": msg.header.frame_id})

    def on_odom(msg):
        p = msg.pose.pose
        with lock:
            odoms.append({"x": float(p.position.x), "y": float(p.position.y),
                          "qz": float(p.orientation.z), "qw": float(p.orientation.w),
                          "frame": msg.header.frame_id, "child": msg.child_frame_id,
                          "stamp_ns": msg.header.stamp.sec * 1_000_000_000 + msg.header.stamp.nanosec})

    def on_clock(msg):
        with lock:
            clocks.append(msg.clock.sec * 1_000_000_000 + msg.clock.nanosec)

    def transforms(into):
        def on_tf(msg):
            with lock:
                for t in msg.transforms:
                    r = t.transform.rotation
                    into.append({"parent": t.header.frame_id, "child": t.child_frame_id,
                                 "stamp_ns": t.header.stamp.sec * 1_000_000_000 + t.header.stamp.nanosec,
                                 "x": float(t.transform.translation.x), "y": float(t.transform.translation.y),
                                 "qz": float(r.z), "qw": float(r.w)})
        return on_tf

    failures = []
    result = {"failures": failures}
    scan_sub = ROS2Subscriber(topic=topic(namespace, "scan"), callback=on_scan, node_name="peer_scan",
                              **typed("sensor_msgs/msg/LaserScan"))
    odom_sub = ROS2Subscriber(topic=topic(namespace, "odom"), callback=on_odom, node_name="peer_odom",
                              **typed("nav_msgs/msg/Odometry"))
    tf_sub = ROS2Subscriber(topic="/tf", callback=transforms(tfs), node_name="peer_tf",
                            **typed("tf2_msgs/msg/TFMessage"))
    tf_static_sub = ROS2Subscriber(topic="/tf_static", callback=transforms(statics), node_name="peer_tf_static",
                                   **typed("tf2_msgs/msg/TFMessage"))
    clock_sub = ROS2Subscriber(topic="/clock", callback=on_clock, node_name="peer_clock",
                               **typed("rosgraph_msgs/msg/Clock"))
    cmd_pub = ROS2Publisher(topic=topic(namespace, "cmd_vel"), node_name="peer_driver",
                            **typed("geometry_msgs/msg/Twist"))
    deadline = time.monotonic() + timeout_s

    def wait_for(cond):
        while time.monotonic() < deadline:
            with lock:
                if cond():
                    return True
            time.sleep(0.05)
        return False

    if not wait_for(lambda: len(scans) >= 3 and len(odoms) >= 3):
        failures.append("fewer than 3 scans and 3 odometry samples arrived")
    if not wait_for(lambda: len(tfs) >= 3 and len(statics) >= 1):
        failures.append("fewer than 3 /tf and 1 /tf_static transforms arrived")
    if not wait_for(lambda: len(clocks) >= 3):
        failures.append("fewer than 3 /clock messages arrived")
    with lock:
        result["clocks"] = len(clocks)
        if any(b < a for a, b in zip(clocks, clocks[1:])):
            failures.append("/clock went back in time")
        # /clock is the world time the stamps are in: the latest scan stamp is at most one laser
        # turn (100 ms) and the poll ahead of the clock seen by then, and never far behind it
        if clocks and scans:
            gap_ns = clocks[-1] - scans[-1]["stamp_ns"]
            result["clock_minus_last_scan_ns"] = gap_ns
            if not -200_000_000 <= gap_ns <= 1_000_000_000:
                failures.append("/clock %d ns is not the time the scans are stamped in (last scan %d ns)"
                                % (clocks[-1], scans[-1]["stamp_ns"]))
    with lock:
        result["tf"] = sorted({(t["parent"], t["child"]) for t in tfs})
        result["tf_static"] = sorted({(t["parent"], t["child"]) for t in statics})
        if result["tf"] != [("odom", "base_link")]:
            failures.append("/tf should carry odom -> base_link only, carried %s" % result["tf"])
        if result["tf_static"] != [("base_link", "laser")]:
            failures.append("/tf_static should carry base_link -> laser only, carried %s" % result["tf_static"])
        if any(s["frame"] != "laser" for s in scans):
            failures.append("a scan not in frame laser: %s" % sorted({s["frame"] for s in scans}))
        if any(o["frame"] != "odom" or o["child"] != "base_link" for o in odoms):
            failures.append("an odometry sample not odom -> base_link")
        # every odom -> base_link transform is an odometry sample's pose at that sample's stamp
        by_stamp = {o["stamp_ns"]: o for o in odoms}
        matched = 0
        for t in tfs:
            o = by_stamp.get(t["stamp_ns"])
            if o is None:
                continue
            matched += 1
            if (t["x"], t["y"], t["qz"], t["qw"]) != (o["x"], o["y"], o["qz"], o["qw"]):
                failures.append("/tf at %d ns is not the odometry pose of that stamp: %s vs %s" % (t["stamp_ns"], t, o))
                break
        result["tf_matched_odometry"] = matched
        if matched == 0:
            failures.append("no /tf transform had the stamp of an odometry sample")
    with lock:
        result["scans"] = len(scans)
        result["odometry"] = len(odoms)
        result["first_scan"] = scans[0] if scans else None
        result["first_odometry"] = odoms[0] if odoms else None
        result["scan_stamps_ns"] = [x["stamp_ns"] for x in scans[:5]]
        start = dict(odoms[-1]) if odoms else None

    expected = (("scan", "sensor_msgs/msg/LaserScan"), ("odom", "nav_msgs/msg/Odometry"),
                ("ground_truth", "nav_msgs/msg/Odometry"), ("cmd_vel", "geometry_msgs/msg/Twist"))

    def graph():
        topics = dict(get_topic_names_and_types(domain_id=0, router_ip=host, router_port=port, timeout=1.0))
        info = get_topic_info(topic(namespace, "scan"), domain_id=0, router_ip=host, router_port=port, timeout=1.0,
                              verbose=True)
        publishers = [] if info is None else [
            {"node": p.node_name, "namespace": p.node_namespace, "qos": p.qos} for p in info.publishers]
        return topics, publishers

    # Liveliness replies lag a freshly connected session's discovery by a moment: ask until
    # the graph is complete or the deadline passes.
    topics, publishers = graph()
    while time.monotonic() < deadline and not (
            all(t in topics.get(topic(namespace, n), []) for n, t in expected)
            and any(p["node"] == "rtaware_sim" for p in publishers)):
        time.sleep(0.2)
        topics, publishers = graph()
    result["topics"] = topics
    result["scan_publishers"] = publishers
    for name, ros_type in expected:
        if ros_type not in topics.get(topic(namespace, name), []):
            failures.append("the graph lacks " + topic(namespace, name) + " of type " + ros_type)
    if not any(p["node"] == "rtaware_sim" for p in publishers):
        failures.append("no /scan publisher of node rtaware_sim in the liveliness tokens")

    if start is not None:
        drive_until = time.monotonic() + 3.0
        Vector3 = session.store.types["geometry_msgs/msg/Vector3"]
        while time.monotonic() < drive_until:
            cmd_pub.publish(linear=Vector3(x=0.3, y=0.0, z=0.0), angular=Vector3(x=0.0, y=0.0, z=0.0))
            time.sleep(0.1)
        cmd_pub.publish(linear=Vector3(x=0.0, y=0.0, z=0.0), angular=Vector3(x=0.0, y=0.0, z=0.0))
        time.sleep(0.5)
        with lock:
            end = odoms[-1]
        moved = math.hypot(end["x"] - start["x"], end["y"] - start["y"])
        result["moved_m"] = moved
        if moved < 0.1:
            failures.append("the robot moved only %.3f m while /cmd_vel asked for 0.3 m/s" % moved)

    for entity in (scan_sub, odom_sub, tf_sub, tf_static_sub, clock_sub, cmd_pub):
        entity.close()
    print(json.dumps(result), flush=True)
    return 1 if failures else 0


def statistics(endpoint, seconds):
    from rosbags.typesys import Stores, get_typestore
    from zenoh_ros2_sdk import ROS2Subscriber, ZenohSession

    host, port = endpoint[len("tcp/"):].rsplit(":", 1)
    port = int(port)
    jazzy = get_typestore(Stores.ROS2_JAZZY)
    session = ZenohSession.get_instance(host, port)
    session.store.register(dict(jazzy.fielddefs))
    name = "statistics_msgs/msg/MetricsMessage"
    lock = threading.Lock()
    seen = {"messages": 0, "sources": {}, "windows": 0, "first": {}, "failures": []}
    windows = set()
    arrivals = {}

    def on_metrics(m):
        now = time.monotonic()
        start = m.window_start.sec * 1_000_000_000 + m.window_start.nanosec
        stop = m.window_stop.sec * 1_000_000_000 + m.window_stop.nanosec
        what = "%s %s" % (m.measurement_source_name, m.metrics_source)
        types = [int(p.data_type) for p in m.statistics]
        values = [float(p.data) for p in m.statistics]
        with lock:
            seen["messages"] += 1
            windows.add(start)
            arrivals.setdefault(what, []).append(now)
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

    sub = ROS2Subscriber(topic="/statistics", callback=on_metrics, node_name="peer_statistics", msg_type=name,
                         msg_definition=jazzy.generate_msgdef(name, ros_version=2)[0],
                         type_hash=jazzy.hash_rihs01(name), router_ip=host, router_port=port)
    time.sleep(seconds)
    sub.close()
    with lock:
        seen["windows"] = len(windows)
        # as `ros2 topic hz` reports a rate: messages after the first over the time since it
        rates = [(len(t) - 1) / (t[-1] - t[0]) for t in arrivals.values() if len(t) > 2]
        seen["rate_hz_per_source_and_metric"] = [min(rates), max(rates)] if rates else None
        if seen["messages"] == 0:
            seen["failures"].append("no MetricsMessage on /statistics")
        print(json.dumps(seen), flush=True)
        return 1 if seen["failures"] else 0


def main():
    parser = argparse.ArgumentParser()
    sub = parser.add_subparsers(dest="command", required=True)
    r = sub.add_parser("router")
    r.add_argument("--listen", required=True)
    c = sub.add_parser("check")
    c.add_argument("--router", required=True)
    c.add_argument("--namespace", default="/")
    c.add_argument("--timeout", type=float, default=60.0)
    st = sub.add_parser("statistics")
    st.add_argument("--router", required=True)
    st.add_argument("--seconds", type=float, default=6.0)
    args = parser.parse_args()
    if args.command == "router":
        return router(args.listen)
    if args.command == "statistics":
        return statistics(args.router, args.seconds)
    return check(args.router, args.namespace, args.timeout)


if __name__ == "__main__":
    sys.exit(main())
