#!/usr/bin/env python3
"""Checks an rtaware recording as ROS 2 tools read it, with code that is not rtaware's.

Usage: check_ros2_profile.py FILE.mcap

- ``mcap`` (CRCs validated): the header's profile is ``ros2``; every channel is ``cdr`` with a
  ``ros2msg`` schema and ``offered_qos_profiles`` metadata (YAML, parsed); the ``rosbag2``
  metadata record holds ``serialized_metadata`` whose per-topic counts match the file; log times
  never go backwards in file order; chunks do not overlap in log time; log times are Unix-epoch
  nanoseconds (after 2020).
- ``rosbags`` ``AnyReader`` (profile check, typestore from the definitions in the file)
  deserializes every message of every channel; each ``topic_type_hash`` equals the RIHS01 hash
  rosbags computes for the Jazzy type, or, for rtaware's own ``rtaware_msgs`` types, for the
  definition in the file; where the file has transforms, every frame has one parent and
  ``/tf`` and ``/tf_static`` connect every header's frame to exactly one root (REP 105: a
  frame name means one thing, e.g. ``world`` for truth and ``odom`` for odometry, never both
  joined by a transform nobody measured); no header stamp (nor transform stamp) is later
  than its message's log time (stamps are when the data was measured, at the latest when it
  was committed).
- ``/clock`` (where the file has it): ``rosgraph_msgs/msg/Clock`` ticks, each carrying its own
  log time, strictly increasing.
- ``/statistics`` (where the file has it): every ``statistics_msgs/msg/MetricsMessage``
  deserialized with rosbags' typestore, shaped as ROS 2's topic statistics publish them (data
  types AVERAGE 1, MINIMUM 2, MAXIMUM 3, STDDEV 4, SAMPLE_COUNT 5 in that order, finite or NaN,
  NaN exactly when the count is 0; windows of one second from the recording's start, logged at
  their end); each whole second has the four metrics of every task on a ``/rtaware/timing/``
  channel and the two of every recorded key, nothing else; and, when nothing was dropped or
  late, every value equals what this script computes itself, by the definitions of docs/ros2.md,
  from the cycles on the timing channels and the commits on the key channels.

Prints one line per check and exits 1 on the first failure. Needs: mcap, rosbags
(see .ci/python-peers.txt).
"""
import math
import struct
import sys
from collections import Counter, defaultdict
from pathlib import Path

from mcap.reader import make_reader
from rosbags.highlevel import AnyReader
from rosbags.typesys import Stores, get_types_from_msg, get_typestore
from ruamel.yaml import YAML  # rosbags' own YAML library

EPOCH_2020_NS = 1_577_836_800 * 10**9
YAML_SAFE = YAML(typ="safe", pure=True)


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def check(condition, message):
    if not condition:
        fail(message)


def main(path):
    with open(path, "rb") as f:
        reader = make_reader(f, validate_crcs=True)
        header = reader.get_header()
        check(header.profile == "ros2", "profile %r, not ros2" % header.profile)
        summary = reader.get_summary()
        for channel in summary.channels.values():
            schema = summary.schemas[channel.schema_id]
            check(channel.message_encoding == "cdr", "%s is %s, not cdr" % (channel.topic, channel.message_encoding))
            check(schema.encoding == "ros2msg", "%s schema is %s" % (channel.topic, schema.encoding))
            qos = YAML_SAFE.load(channel.metadata.get("offered_qos_profiles", ""))
            check(isinstance(qos, list) and qos and "reliability" in qos[0], "%s offered_qos_profiles: %r"
                  % (channel.topic, channel.metadata.get("offered_qos_profiles")))
        print("ok: profile ros2, %d channels all cdr with ros2msg schemas and offered QoS" % len(summary.channels))
        jazzy = get_typestore(Stores.ROS2_JAZZY)
        ours = set()
        for schema in summary.schemas.values():
            if schema.name.startswith("rtaware_msgs/"):
                # rtaware's own types have no dependencies: the schema is the .msg definition
                jazzy.register(get_types_from_msg(schema.data.decode(), schema.name))
                ours.add(schema.name)
        hashed = 0
        for channel in summary.channels.values():
            declared = channel.metadata.get("topic_type_hash")
            name = summary.schemas[channel.schema_id].name
            check(declared or name not in ours, "%s of %s has no topic_type_hash" % (channel.topic, name))
            if declared:
                check(declared == jazzy.hash_rihs01(name), "%s: topic_type_hash %s, rosbags computes %s"
                      % (channel.topic, declared, jazzy.hash_rihs01(name)))
                hashed += 1
        print("ok: %d topic_type_hash values equal rosbags' RIHS01 of the Jazzy types and of %s"
              % (hashed, ", ".join(sorted(ours)) or "no rtaware_msgs type"))

        previous, counts, count, last_tick = None, Counter(), 0, None
        for schema, channel, message in reader.iter_messages(log_time_order=False):
            if previous is not None and message.log_time < previous:
                fail("log time goes back on %s: %d after %d" % (channel.topic, message.log_time, previous))
            previous = message.log_time
            counts[channel.topic] += 1
            count += 1
            if channel.topic == "/clock":
                check(schema.name == "rosgraph_msgs/msg/Clock", "/clock is %s" % schema.name)
                sec, nanosec = struct.unpack_from("<iI", message.data, 4)
                tick = sec * 10**9 + nanosec
                check(tick == message.log_time, "/clock says %d at log time %d" % (tick, message.log_time))
                check(last_tick is None or tick > last_tick, "/clock goes from %s to %d" % (last_tick, tick))
                last_tick = tick
        check(count == summary.statistics.message_count, "summary says %d messages, read %d"
              % (summary.statistics.message_count, count))
        check(count == 0 or summary.statistics.message_start_time > EPOCH_2020_NS,
              "log times are not Unix-epoch ns: first %d" % summary.statistics.message_start_time)
        print("ok: %d messages in log-time order, epoch log times from %d" % (count, summary.statistics.message_start_time))
        if counts["/clock"]:
            print("ok: %d /clock ticks, each its log time, increasing" % counts["/clock"])

        chunks = sorted(summary.chunk_indexes, key=lambda c: c.chunk_start_offset)
        for a, b in zip(chunks, chunks[1:]):
            check(a.message_end_time < b.message_start_time, "chunks overlap or share an instant: %d..%d then %d..%d"
                  % (a.message_start_time, a.message_end_time, b.message_start_time, b.message_end_time))
        print("ok: %d chunks, none overlapping" % len(chunks))

        check_statistics(reader, summary, jazzy)

        bags = [m for m in reader.iter_metadata() if m.name == "rosbag2"]
        check(len(bags) == 1, "%d rosbag2 metadata records" % len(bags))
        info = YAML_SAFE.load(bags[0].metadata["serialized_metadata"])["rosbag2_bagfile_information"]
        check(info["message_count"] == count, "rosbag2 metadata counts %s messages" % info["message_count"])
        for t in info["topics_with_message_count"]:
            name = t["topic_metadata"]["name"]
            check(t["message_count"] == counts[name], "rosbag2 metadata: %s has %s, file %d"
                  % (name, t["message_count"], counts[name]))
            check(t["topic_metadata"]["serialization_format"] == "cdr", "serialization_format")
        print("ok: rosbag2 metadata record (version %s) matches the file" % info["version"])

    with AnyReader([Path(path)]) as bag:
        decoded, measured = Counter(), Counter()
        edges, frames = set(), set()

        def stamped(topic, header, timestamp):
            stamp = header.stamp.sec * 10**9 + header.stamp.nanosec
            check(stamp <= timestamp, "%s stamped %d, after its log time %d" % (topic, stamp, timestamp))
            if stamp < timestamp:
                measured[topic] += 1

        for connection, timestamp, raw in bag.messages():
            msg = bag.deserialize(raw, connection.msgtype)
            decoded[connection.topic] += 1
            if connection.msgtype == "tf2_msgs/msg/TFMessage":
                for t in msg.transforms:
                    edges.add((t.header.frame_id, t.child_frame_id))
                    stamped(connection.topic, t.header, timestamp)
            elif hasattr(msg, "header"):
                # A health array is about the system, not a place: its frame is empty, as
                # diagnostic_updater leaves it.
                if not (connection.msgtype == "diagnostic_msgs/msg/DiagnosticArray" and msg.header.frame_id == ""):
                    frames.add(msg.header.frame_id)
                stamped(connection.topic, msg.header, timestamp)
            if connection.msgtype == "nav_msgs/msg/Odometry":
                frames.add(msg.child_frame_id)
        check(sum(decoded.values()) == count, "rosbags read %d of %d messages" % (sum(decoded.values()), count))
        types = sorted({c.msgtype for c in bag.connections})
    print("ok: rosbags AnyReader deserialized all %d messages on %d topics (%s)" % (count, len(decoded), ", ".join(types)))
    print("ok: no header stamp after its log time; stamped before it (when measured): %s"
          % (", ".join("%s %d" % kv for kv in sorted(measured.items())) or "none"))
    if edges:
        # tf's rule: a frame has one parent. REP 105's: each tree is rooted at a fixed frame, and a
        # frame name means one thing, so no frame hangs below two roots (that would claim the
        # roots, e.g. the world's and odometry's frames, are one).
        parents = {}
        for a, b in edges:
            parents.setdefault(b, set()).add(a)
        check(all(len(p) == 1 for p in parents.values()),
              "frames with more than one parent: %s" % sorted((b, sorted(p)) for b, p in parents.items() if len(p) > 1))
        roots = sorted({a for a, _ in edges} - set(parents))

        def below(root):
            reached, todo = {root}, [root]
            while todo:
                parent = todo.pop()
                for a, b in edges:
                    if a == parent and b not in reached:
                        reached.add(b)
                        todo.append(b)
            return reached

        trees = {r: below(r) for r in roots}
        for frame in frames | {b for _, b in edges}:
            under = [r for r in roots if frame in trees[r]]
            check(len(under) == 1, "frame %s is under %s of the roots %s" % (frame, len(under), roots))
        print("ok: /tf and /tf_static connect every header frame to one root of %s (%s)"
              % (", ".join(roots), ", ".join("%s->%s" % e for e in sorted(edges))))


TASK_METRICS = ("release_lateness", "execution_time", "input_age", "deadline_misses")
KEY_METRICS = ("message_period", "message_age")
WINDOW_NS = 10**9


class Moments:
    """One metric's samples in one window, kept whole (this script's own arithmetic)."""

    def __init__(self):
        self.samples = []

    def add(self, x):
        self.samples.append(x)

    def expected(self):
        n = len(self.samples)
        if n == 0:
            return [math.nan] * 4 + [0.0]
        mean = sum(self.samples) / n
        return [mean, min(self.samples), max(self.samples),
                math.sqrt(sum((x - mean) ** 2 for x in self.samples) / n), float(n)]


def check_statistics(reader, summary, store):
    channels = summary.channels.values()
    statistics = [c for c in channels if c.topic == "/statistics"]
    if not statistics:
        return
    schema = summary.schemas[statistics[0].schema_id].name
    check(schema == "statistics_msgs/msg/MetricsMessage", "/statistics is %s" % schema)
    run = {m.name: m.metadata for m in reader.iter_metadata()}
    offset = int(run["rtaware.run"]["log_time_offset_ns"])
    origin = offset + int(run["rtaware.run"]["world_start_ns"])
    counted = run["rtaware.statistics"]
    tasks = {c.id: c.topic[len("/rtaware/timing/"):] for c in channels if c.topic.startswith("/rtaware/timing/")}
    inputs = {c.topic[len("/rtaware/timing/"):]: [k for k in c.metadata.get("inputs", "").split(",") if k]
              for c in channels if c.topic.startswith("/rtaware/timing/")}
    key_channels = {}
    for c in sorted(channels, key=lambda c: c.id):
        if c.metadata.get("sequence") == "generation" and "key" in c.metadata:
            key_channels.setdefault(c.metadata["key"], c.id)
    keys = {cid: key for key, cid in key_channels.items()}

    published = defaultdict(dict)  # window start -> {(source, metric): (unit, values)}
    cycles = defaultdict(list)  # task -> [(sequence, TaskCycle)]
    commits = defaultdict(dict)  # key -> {generation: world ns}
    for _schema, channel, message in reader.iter_messages(log_time_order=False):
        if channel.topic == "/statistics":
            m = store.deserialize_cdr(message.data, "statistics_msgs/msg/MetricsMessage")
            start = m.window_start.sec * 10**9 + m.window_start.nanosec
            stop = m.window_stop.sec * 10**9 + m.window_stop.nanosec
            check(stop - start == WINDOW_NS, "a window of %d ns" % (stop - start))
            check((start - origin) % WINDOW_NS == 0, "a window not on a second of the recording: %d" % start)
            check(message.log_time == stop, "logged at %d, not at its window's end %d" % (message.log_time, stop))
            types = [p.data_type for p in m.statistics]
            check(types == [1, 2, 3, 4, 5], "%s %s: data types %s" % (m.measurement_source_name, m.metrics_source, types))
            values = [p.data for p in m.statistics]
            check(not any(math.isinf(v) for v in values), "an infinite statistic: %s" % values)
            count = values[4]
            check(count >= 0 and count == int(count), "sample count %s" % count)
            check(all(math.isnan(v) == (count == 0) for v in values[:4]), "NaN exactly without samples: %s" % values)
            unit = "count" if m.metrics_source == "deadline_misses" else "ms"
            check(m.unit == unit, "%s in %r, not %r" % (m.metrics_source, m.unit, unit))
            what = (m.measurement_source_name, m.metrics_source)
            check(what not in published[start], "%s twice in the window at %d" % (what, start))
            published[start][what] = values
        elif channel.id in tasks:
            cycles[tasks[channel.id]].append((message.sequence, store.deserialize_cdr(message.data, _schema.name)))
        elif channel.id in keys:
            commits[keys[channel.id]][message.sequence] = message.log_time - offset

    starts = sorted(published)
    check(starts == [origin + k * WINDOW_NS for k in range(len(starts))], "windows not one every second from the start")
    check(len(starts) == int(counted["windows"]), "%d windows, the metadata says %s" % (len(starts), counted["windows"]))
    expected_sources = {(t, m) for t in inputs for m in TASK_METRICS} | {(k, m) for k in key_channels for m in KEY_METRICS}
    for start in starts:
        check(set(published[start]) == expected_sources, "the window at %d has %s, not every task's and key's metrics"
              % (start, sorted(set(published[start]) ^ expected_sources)))
    print("ok: /statistics decoded by rosbags: %d whole seconds, each with %s of every task (%s) and %s of every key "
          "(%s)" % (len(starts), ", ".join(TASK_METRICS), ", ".join(sorted(inputs)), ", ".join(KEY_METRICS),
                    ", ".join(sorted(key_channels))))

    gaps = [t for t, cs in cycles.items() if [s for s, _ in cs] != list(range(len(cs)))]
    gaps += [k for k, cs in commits.items() if sorted(cs) != list(range(1, len(cs) + 1))]
    if gaps or counted["late_records"] != "0" or counted["unmatched_ages"] != "0":
        print("ok: /statistics not recomputed: records dropped (%s) or late (%s) or ages unmatched (%s)"
              % (", ".join(gaps) or "none", counted["late_records"], counted["unmatched_ages"]))
        return
    windows = defaultdict(lambda: defaultdict(Moments))

    def window(world_ns):
        return origin + (world_ns + offset - origin) // WINDOW_NS * WINDOW_NS

    for key, by_generation in commits.items():
        for g, t in by_generation.items():
            if g - 1 in by_generation:
                windows[window(t)][(key, "message_period")].add((t - by_generation[g - 1]) / 1e6)
    for task, records in cycles.items():
        held = [0] * len(inputs[task])
        for _seq, c in sorted(records, key=lambda r: r[0]):
            w = windows[window(c.end_ns)]
            if c.outcome == "skipped":
                for _ in range(c.skipped_releases):
                    w[(task, "deadline_misses")].add(1.0)
                continue
            w[(task, "release_lateness")].add(max(0, c.start_ns - c.release_ns) / 1e6)
            w[(task, "execution_time")].add((c.end_ns - c.start_ns) / 1e6)
            if c.outcome != "error":
                w[(task, "deadline_misses")].add(1.0 if c.outcome == "miss" else 0.0)
            ages = []
            for i, g in enumerate(int(x) for x in c.input_generations):
                key = inputs[task][i]
                fresh = g != held[i]
                held[i] = g
                if g == 0 or key not in commits:
                    continue
                age = (c.start_ns - commits[key][g]) / 1e6
                ages.append(age)
                if fresh:
                    w[(key, "message_age")].add(age)
            if ages:
                w[(task, "input_age")].add(max(ages))
    compared = 0
    for start in starts:
        for what, values in published[start].items():
            want = windows[start][what].expected()
            for name, got, expected in zip(("average", "min", "max", "stddev", "count"), values, want):
                same = (math.isnan(got) and math.isnan(expected)) or math.isclose(got, expected, rel_tol=1e-9,
                                                                                  abs_tol=1e-9)
                check(same, "%s %s in the window at %d: %s %r, computed from the recording %r"
                      % (what[0], what[1], start, name, got, expected))
            compared += 1
    print("ok: /statistics equals what the timing and key channels give: %d messages recomputed" % compared)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print(__doc__)
        sys.exit(2)
    main(sys.argv[1])
