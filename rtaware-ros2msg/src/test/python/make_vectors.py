#!/usr/bin/env python3
"""Reference vectors for rtaware-ros2msg, made by an independent serializer (rosbags).

For every ROS 2 message type rtaware encodes, this script writes the message definition in the
form MCAP's ``ros2msg`` schema encoding wants (rosbags ``generate_msgdef``), the RIHS01 type
hash of the Jazzy definitions (rosbags ``hash_rihs01``), and CDR bytes (rosbags
``serialize_cdr``, little endian) of a few sample messages. Samples are given in rtaware's
terms (metres, radians, a stamp in ns); the mapping to ROS fields below is the one documented
in rtaware-ros2msg's codecs, written again here independently of the Java code.

The output is committed as ``src/test/resources/io/rtaware/ros2msg/vectors.json`` so that the
Java tests need no Python. Regenerate after changing a sample:

    python3 -m venv ~/.cache/rtaware/py-venv            # once, outside the clone
    ~/.cache/rtaware/py-venv/bin/pip install rosbags    # 0.11.9 was used
    ~/.cache/rtaware/py-venv/bin/python rtaware-ros2msg/src/test/python/make_vectors.py \
        > rtaware-ros2msg/src/test/resources/io/rtaware/ros2msg/vectors.json
"""
import json
import math

import numpy as np
from rosbags.typesys import Stores, get_typestore

TS = get_typestore(Stores.ROS2_JAZZY)
T = TS.types


def stamp(ns):
    return T['builtin_interfaces/msg/Time'](sec=ns // 1_000_000_000, nanosec=ns % 1_000_000_000)


def header(s):
    return T['std_msgs/msg/Header'](stamp=stamp(s['stamp_ns']), frame_id=s['frame_id'])


def quat(yaw):
    # rotation about z only
    return T['geometry_msgs/msg/Quaternion'](x=0.0, y=0.0, z=math.sin(yaw / 2), w=math.cos(yaw / 2))


def point(x, y):
    return T['geometry_msgs/msg/Point'](x=float(x), y=float(y), z=0.0)


def pose(x, y, yaw):
    return T['geometry_msgs/msg/Pose'](position=point(x, y), orientation=quat(yaw))


def vec3(x, y, z):
    return T['geometry_msgs/msg/Vector3'](x=float(x), y=float(y), z=float(z))


def laser(s):
    n = len(s['ranges_m'])
    inc = (s['max_angle_rad'] - s['min_angle_rad']) / (n - 1) if n >= 2 else 0.0
    return T['sensor_msgs/msg/LaserScan'](
        header=header(s), angle_min=s['min_angle_rad'], angle_max=s['max_angle_rad'],
        angle_increment=float(np.float32(inc)), time_increment=0.0, scan_time=0.0,
        range_min=0.0, range_max=s['max_range_m'],
        ranges=np.array(s['ranges_m'], dtype=np.float32), intensities=np.array([], dtype=np.float32))


def odometry(s):
    cov = np.zeros(36, dtype=np.float64)
    return T['nav_msgs/msg/Odometry'](
        header=header(s), child_frame_id=s['child_frame_id'],
        pose=T['geometry_msgs/msg/PoseWithCovariance'](pose=pose(s['x_m'], s['y_m'], s['yaw_rad']), covariance=cov),
        twist=T['geometry_msgs/msg/TwistWithCovariance'](
            twist=T['geometry_msgs/msg/Twist'](linear=vec3(s['vx_mps'], s['vy_mps'], 0),
                                               angular=vec3(0, 0, s['omega_rad_per_sec'])),
            covariance=cov))


def twist(s):
    return T['geometry_msgs/msg/Twist'](linear=vec3(s['vx_mps'], 0, 0), angular=vec3(0, 0, s['omega_rad_per_sec']))


def path(s):
    h = header(s)
    poses = [T['geometry_msgs/msg/PoseStamped'](header=h, pose=pose(x, y, 0.0)) for x, y in zip(s['x_m'], s['y_m'])]
    return T['nav_msgs/msg/Path'](header=h, poses=poses)


def grid(s):
    info = T['nav_msgs/msg/MapMetaData'](
        map_load_time=stamp(s['stamp_ns']), resolution=s['resolution_m'], width=s['width'], height=s['height'],
        origin=pose(s['origin_x_m'], s['origin_y_m'], 0.0))
    return T['nav_msgs/msg/OccupancyGrid'](header=header(s), info=info, data=np.array(s['cells'], dtype=np.int8))


def pose_stamped(s):
    return T['geometry_msgs/msg/PoseStamped'](header=header(s), pose=pose(s['x_m'], s['y_m'], s['yaw_rad']))


def diagnostics(s):
    statuses = [T['diagnostic_msgs/msg/DiagnosticStatus'](
        level=st['level'], name=st['name'], message=st['message'], hardware_id=st['hardware_id'],
        values=[T['diagnostic_msgs/msg/KeyValue'](key=k, value=v) for k, v in st['values']])
        for st in s['status']]
    return T['diagnostic_msgs/msg/DiagnosticArray'](header=header(s), status=statuses)


def metrics(s):
    # a data point's value None stands for NaN (JSON has no NaN)
    points = [T['statistics_msgs/msg/StatisticDataPoint'](data_type=t, data=float('nan') if v is None else float(v))
              for t, v in s['statistics']]
    return T['statistics_msgs/msg/MetricsMessage'](
        measurement_source_name=s['measurement_source_name'], metrics_source=s['metrics_source'], unit=s['unit'],
        window_start=stamp(s['window_start_ns']), window_stop=stamp(s['window_stop_ns']), statistics=points)


# stamps: one with a non-zero nanosecond part, one at zero
SAMPLES = {
    'sensor_msgs/msg/LaserScan': (laser, [
        dict(stamp_ns=12_345_678_901, frame_id='laser', min_angle_rad=-1.5707963705062866,
             max_angle_rad=1.5707963705062866, max_range_m=8.0, ranges_m=[0.5, 1.25, 8.0, 3.75, 2.0]),
        dict(stamp_ns=0, frame_id='', min_angle_rad=0.0, max_angle_rad=0.0, max_range_m=5.0, ranges_m=[]),
    ]),
    'nav_msgs/msg/Odometry': (odometry, [
        dict(stamp_ns=1_500_000_000, frame_id='odom', child_frame_id='base_link', x_m=1.5, y_m=-2.25,
             yaw_rad=0.75, vx_mps=0.4, vy_mps=0.0, omega_rad_per_sec=-0.3),
        dict(stamp_ns=7, frame_id='map', child_frame_id='base_link', x_m=0.0, y_m=0.0, yaw_rad=0.0,
             vx_mps=0.0, vy_mps=0.0, omega_rad_per_sec=0.0),
    ]),
    'geometry_msgs/msg/Twist': (twist, [
        dict(vx_mps=0.35, omega_rad_per_sec=-0.8),
        dict(vx_mps=0.0, omega_rad_per_sec=0.0),
    ]),
    'nav_msgs/msg/Path': (path, [
        dict(stamp_ns=2_000_000_001, frame_id='map', x_m=[0.0, 0.5, 1.0], y_m=[0.0, 0.25, 0.75]),
        dict(stamp_ns=3, frame_id='map', x_m=[], y_m=[]),
    ]),
    'nav_msgs/msg/OccupancyGrid': (grid, [
        dict(stamp_ns=4_250_000_000, frame_id='map', width=3, height=2, resolution_m=0.05,
             origin_x_m=-1.0, origin_y_m=-0.5, cells=[-1, 0, 100, 0, -1, 100]),
    ]),
    'geometry_msgs/msg/PoseStamped': (pose_stamped, [
        dict(stamp_ns=999_999_999, frame_id='world', x_m=3.0, y_m=4.5, yaw_rad=-2.0),
    ]),
    'diagnostic_msgs/msg/DiagnosticArray': (diagnostics, [
        dict(stamp_ns=5_000_000_000, frame_id='', status=[
            dict(level=0, name='rtaware: planner', message='ok', hardware_id='',
                 values=[['period_ms', '100'], ['misses', '0']]),
            dict(level=1, name='rtaware: mapper', message='late', hardware_id='host', values=[]),
        ]),
    ]),
    # as ROS 2's topic statistics order them: AVERAGE 1, MINIMUM 2, MAXIMUM 3, STDDEV 4, SAMPLE_COUNT 5
    'statistics_msgs/msg/MetricsMessage': (metrics, [
        dict(measurement_source_name='obstacle', metrics_source='execution_time', unit='ms',
             window_start_ns=1_764_000_000_250_000_001, window_stop_ns=1_764_000_001_250_000_001,
             statistics=[[1, 2.5], [2, 0.125], [3, 7.75], [4, 1.0625], [5, 20]]),
        dict(measurement_source_name='laser', metrics_source='message_age', unit='ms',
             window_start_ns=0, window_stop_ns=1_000_000_000,
             statistics=[[1, None], [2, None], [3, None], [4, None], [5, 0]]),
    ]),
}


def main():
    out = []
    for typename, (build, samples) in SAMPLES.items():
        msgdef, _md5 = TS.generate_msgdef(typename, ros_version=2)
        entry = {
            'type': typename,
            'msgdef': msgdef,
            'rihs01': TS.hash_rihs01(typename),
            'samples': [],
        }
        for s in samples:
            cdr = TS.serialize_cdr(build(s), typename, little_endian=True)
            entry['samples'].append({'values': s, 'cdr_hex': bytes(cdr).hex()})
        out.append(entry)
    print(json.dumps({'generator': 'rosbags (Stores.ROS2_JAZZY)', 'types': out}, indent=1))


if __name__ == '__main__':
    main()
