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
  definition in the file; where the file has transforms, ``/tf`` and ``/tf_static`` connect
  every header's frame to ``map`` (REP 105); no header stamp (nor transform stamp) is later
  than its message's log time (stamps are when the data was measured, at the latest when it
  was committed).
- ``/clock`` (where the file has it): ``rosgraph_msgs/msg/Clock`` ticks, each carrying its own
  log time, strictly increasing.

Prints one line per check and exits 1 on the first failure. Needs: mcap, rosbags
(see .ci/python-peers.txt).
"""
import struct
import sys
from collections import Counter
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
        reached, todo = {"map"}, ["map"]
        while todo:
            parent = todo.pop()
            for a, b in edges:
                if a == parent and b not in reached:
                    reached.add(b)
                    todo.append(b)
        check(frames <= reached, "frames not connected to map by /tf and /tf_static: %s" % sorted(frames - reached))
        print("ok: /tf and /tf_static connect every header frame to map (%s)"
              % ", ".join("%s->%s" % e for e in sorted(edges)))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print(__doc__)
        sys.exit(2)
    main(sys.argv[1])
