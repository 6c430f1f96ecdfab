#!/usr/bin/env python3
"""A simulated ROS 2 robot as Touchline meets one on the field: a Foxglove WebSocket server made
with the Foxglove SDK (what foxglove_bridge is built on; it speaks foxglove.sdk.v1) publishing

  /rosout        rcl_interfaces/msg/Log             ros2msg / cdr
  /pose          geometry_msgs/msg/PoseStamped      ros2msg / cdr   (field coordinates, metres)
  /joint_states  sensor_msgs/msg/JointState         ros2msg / cdr
  /robot_state   JSON (battery, temperature, the game state the robot believes)
  /heading       foxglove.Vector2                   protobuf

with the CDR bytes made by mcap_ros2's serializer (nobody at Touchline wrote it). It offers
parameters (get/set), client publish and a service, and says on /rosout what a client sent it,
so a test sees through the bridge that a parameter set or a publish arrived.

    python3 sim_ros2_robot.py --port 8765 --name booster-1 [--rate 20] [--seconds 0]

Prints "listening on port N" once it serves (port 0 takes a free one). Stops after --seconds
(0: never) or on SIGTERM/SIGINT.
"""
import argparse
import json
import math
import signal
import threading
import time

import foxglove
from foxglove import Capability, Channel, Parameter, Schema
from foxglove.channels import Vector2Channel
from foxglove.messages import Vector2
from foxglove.websocket import Service, ServiceSchema, MessageSchema
from mcap_ros2._dynamic import serialize_dynamic

SEP = "=" * 80 + "\n"
TIME = "int32 sec\nuint32 nanosec\n"
HEADER = "builtin_interfaces/Time stamp\nstring frame_id\n"

LOG = ("byte DEBUG=10\nbyte INFO=20\nbyte WARN=30\nbyte ERROR=40\nbyte FATAL=50\n"
       "builtin_interfaces/Time stamp\nuint8 level\nstring name\nstring msg\nstring file\nstring function\nuint32 line\n"
       + SEP + "MSG: builtin_interfaces/Time\n" + TIME)
POSE_STAMPED = ("std_msgs/Header header\nPose pose\n"
                + SEP + "MSG: std_msgs/Header\n" + HEADER
                + SEP + "MSG: builtin_interfaces/Time\n" + TIME
                + SEP + "MSG: geometry_msgs/Pose\nPoint position\nQuaternion orientation\n"
                + SEP + "MSG: geometry_msgs/Point\nfloat64 x\nfloat64 y\nfloat64 z\n"
                + SEP + "MSG: geometry_msgs/Quaternion\nfloat64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n")
JOINT_STATE = ("std_msgs/Header header\nstring[] name\nfloat64[] position\nfloat64[] velocity\nfloat64[] effort\n"
               + SEP + "MSG: std_msgs/Header\n" + HEADER
               + SEP + "MSG: builtin_interfaces/Time\n" + TIME)
STRING = "string data\n"

JOINTS = ["head_yaw", "head_pitch", "l_hip_pitch", "l_knee", "r_hip_pitch", "r_knee"]


def ros2_channel(topic, type_name, definition):
    encode = serialize_dynamic(type_name, definition)[type_name]
    channel = Channel(topic, message_encoding="cdr",
                      schema=Schema(name=type_name, encoding="ros2msg", data=definition.encode()))
    return channel, encode


class Robot(foxglove.websocket.ServerListener):

    def __init__(self, name):
        self.name = name
        self.lock = threading.Lock()
        self.parameters = {"walk.speed": 0.3, "debug.draw_ball": False, "role": "striker"}
        self.heard = []  # what clients sent: said on /rosout by the publishing loop

    def on_get_parameters(self, client, param_names, request_id=None):
        with self.lock:
            return [Parameter(n, value=v) for n, v in self.parameters.items() if not param_names or n in param_names]

    def on_set_parameters(self, client, parameters, request_id=None):
        with self.lock:
            for p in parameters:
                self.parameters[p.name] = p.get_value()
                self.heard.append("parameter %s set to %s" % (p.name, json.dumps(p.get_value())))
            return [Parameter(n, value=v) for n, v in self.parameters.items()]

    def on_client_advertise(self, client, channel):
        with self.lock:
            self.heard.append("client advertised %s (%s)" % (channel.topic, channel.encoding))

    def on_message_data(self, client, client_channel_id, data):
        with self.lock:
            try:
                text = data.decode("utf-8")
            except UnicodeDecodeError:
                text = "%d bytes" % len(data)
            self.heard.append("client published on channel %d: %s" % (client_channel_id, text))

    def take_heard(self):
        with self.lock:
            out, self.heard = self.heard, []
            return out


def stamp(now):
    return {"sec": int(now), "nanosec": int((now % 1) * 1e9)}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--port", type=int, default=8765)
    ap.add_argument("--name", default="ros2-robot")
    ap.add_argument("--rate", type=float, default=20.0, help="pose and joint messages per second")
    ap.add_argument("--seconds", type=float, default=0.0, help="stop after this long (0: never)")
    ap.add_argument("--game-state", default="PLAYING", help="the game state the robot reports on /robot_state")
    ap.add_argument("--centre", default="0,0", help="the centre of the robot's walk on the field, metres: X,Y")
    args = ap.parse_args()
    cx, cy = (float(v) for v in args.centre.split(","))

    robot = Robot(args.name)
    services = [Service(name="/%s/say" % args.name, schema=ServiceSchema(name="std_srvs/srv/Trigger"),
                        handler=lambda req: json.dumps({"success": True, "message": "said"}).encode())]
    server = foxglove.start_server(name=args.name, host="127.0.0.1", port=args.port, server_listener=robot,
                                   capabilities=[Capability.ClientPublish, Capability.Parameters, Capability.Services],
                                   supported_encodings=["json", "cdr"], services=services)
    log, encode_log = ros2_channel("/rosout", "rcl_interfaces/msg/Log", LOG)
    pose, encode_pose = ros2_channel("/pose", "geometry_msgs/msg/PoseStamped", POSE_STAMPED)
    joints, encode_joints = ros2_channel("/joint_states", "sensor_msgs/msg/JointState", JOINT_STATE)
    state = Channel("/robot_state", message_encoding="json")
    heading = Vector2Channel("/heading")
    print("listening on port %d" % server.port, flush=True)

    stop = threading.Event()
    signal.signal(signal.SIGTERM, lambda *a: stop.set())
    start = time.time()
    n = 0
    while not stop.is_set() and (args.seconds <= 0 or time.time() - start < args.seconds):
        now = time.time()
        t = now - start
        angle = 0.4 * t
        x, y, theta = cx + 1.2 * math.cos(angle), cy + 0.8 * math.sin(angle), angle + math.pi / 2
        pose.log(encode_pose({"header": {"stamp": stamp(now), "frame_id": "field"},
                              "pose": {"position": {"x": x, "y": y, "z": 0.0},
                                       "orientation": {"x": 0.0, "y": 0.0, "z": math.sin(theta / 2),
                                                       "w": math.cos(theta / 2)}}}))
        joints.log(encode_joints({"header": {"stamp": stamp(now), "frame_id": ""}, "name": JOINTS,
                                  "position": [0.3 * math.sin(t + i) for i in range(len(JOINTS))],
                                  "velocity": [0.0] * len(JOINTS), "effort": [1.0 + i for i in range(len(JOINTS))]}))
        heading.log(Vector2(x=math.cos(theta), y=math.sin(theta)))
        for said in robot.take_heard():
            print(said, flush=True)
            log.log(encode_log({"stamp": stamp(now), "level": 20, "name": args.name, "msg": said,
                                "file": "sim_ros2_robot.py", "function": "on_client", "line": 1}))
        if n % max(1, int(args.rate)) == 0:
            log.log(encode_log({"stamp": stamp(now), "level": 20 if n % 3 else 30, "name": args.name + "/behavior",
                                "msg": "walking to (%.2f, %.2f)" % (x, y), "file": "behavior.py",
                                "function": "tick", "line": 42}))
            state.log({"battery": {"percentage": max(0.0, 95.0 - t / 60.0)}, "temperature": 41.5 + math.sin(t),
                       "game_state": args.game_state})
        n += 1
        stop.wait(1.0 / args.rate)
    server.stop()


if __name__ == "__main__":
    main()
