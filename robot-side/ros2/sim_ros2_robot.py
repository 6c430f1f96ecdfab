#!/usr/bin/env python3
"""A simulated ROS 2 robot as Touchline meets one on the field: a Foxglove WebSocket server made
with the Foxglove SDK (what foxglove_bridge is built on; it speaks foxglove.sdk.v1) publishing

  /rosout        rcl_interfaces/msg/Log             ros2msg / cdr
  /pose          geometry_msgs/msg/PoseStamped      ros2msg / cdr   (in map: field coordinates, metres)
  /tf            tf2_msgs/msg/TFMessage             ros2msg / cdr   (map→odom, odom→base_link; 10 Hz)
  /tf_static     tf2_msgs/msg/TFMessage             ros2msg / cdr   (base_link→camera; 1 Hz)
  /joint_states  sensor_msgs/msg/JointState         ros2msg / cdr   (24 joints)
  /camera/image/compressed  sensor_msgs/msg/CompressedImage  ros2msg / cdr  (a 64×48 JPEG, 5 Hz)
  /markers       visualization_msgs/msg/MarkerArray ros2msg / cdr   (ball, path, circle in map; text in base_link; 5 Hz)
  /diagnostics   diagnostic_msgs/msg/DiagnosticArray ros2msg / cdr  (battery, temperature; 1 Hz)
  /robot_state   JSON (battery, temperature, the game state the robot believes)
  /heading       foxglove.Vector2                   protobuf

with the CDR bytes made by mcap_ros2's serializer (nobody at Touchline wrote it). It offers
parameters (get/set), client publish (JSON, or CDR it reads back with mcap_ros2 by the schema the
client advertised) and three services (/NAME/say answers JSON, /NAME/check a CDR
std_srvs/srv/Trigger response, /NAME/kick always fails), and says on /rosout what a client sent
it, so a test sees through the bridge that a parameter set or a publish arrived.

    python3 sim_ros2_robot.py --port 8765 --name booster-1 [--rate 20] [--seconds 0]
                              [--camera-jpeg FILE] [--camera-hz 5] [--centre X,Y] [--radius 1]
                              [--odom X,Y,YAW] [--heading YAW]

Prints "listening on port N" once it serves (port 0 takes a free one). Stops after --seconds
(0: never) or on SIGTERM/SIGINT, and then prints "sent N": the messages it logged on channels a
client had subscribed to (what a client that lost nothing received; the benchmark
`./touchline bench bridges` compares them). --camera-jpeg sends that file's JPEG (e.g. 640×480)
instead of the built-in 64×48 one, at --camera-hz. The robot walks an ellipse (1.2 m × 0.8 m times
--radius; 0: it turns on the spot) around --centre of map; its odometry frame lies at --odom of map
(metres, radians: how far its odometry drifted), so its TF tree is map→odom→base_link→camera.
--heading holds its heading in map (radians) rather than turning with its walk.
"""
import argparse
import base64
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
from mcap_ros2._dynamic import generate_dynamic, serialize_dynamic

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
COMPRESSED_IMAGE = ("std_msgs/Header header\nstring format\nuint8[] data\n"
                    + SEP + "MSG: std_msgs/Header\n" + HEADER
                    + SEP + "MSG: builtin_interfaces/Time\n" + TIME)
MARKER_ARRAY = ("visualization_msgs/Marker[] markers\n"
                + SEP + "MSG: visualization_msgs/Marker\n"
                "int32 ARROW=0\nint32 CUBE=1\nint32 SPHERE=2\nint32 CYLINDER=3\nint32 LINE_STRIP=4\nint32 LINE_LIST=5\n"
                "int32 CUBE_LIST=6\nint32 SPHERE_LIST=7\nint32 POINTS=8\nint32 TEXT_VIEW_FACING=9\n"
                "int32 MESH_RESOURCE=10\nint32 TRIANGLE_LIST=11\nint32 ADD=0\nint32 MODIFY=0\nint32 DELETE=2\n"
                "int32 DELETEALL=3\n"
                "std_msgs/Header header\nstring ns\nint32 id\nint32 type\nint32 action\ngeometry_msgs/Pose pose\n"
                "geometry_msgs/Vector3 scale\nstd_msgs/ColorRGBA color\nbuiltin_interfaces/Duration lifetime\n"
                "bool frame_locked\ngeometry_msgs/Point[] points\nstd_msgs/ColorRGBA[] colors\nstring text\n"
                "string mesh_resource\nbool mesh_use_embedded_materials\n"
                + SEP + "MSG: std_msgs/Header\n" + HEADER
                + SEP + "MSG: builtin_interfaces/Time\n" + TIME
                + SEP + "MSG: builtin_interfaces/Duration\n" + TIME
                + SEP + "MSG: geometry_msgs/Pose\nPoint position\nQuaternion orientation\n"
                + SEP + "MSG: geometry_msgs/Point\nfloat64 x\nfloat64 y\nfloat64 z\n"
                + SEP + "MSG: geometry_msgs/Quaternion\nfloat64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n"
                + SEP + "MSG: geometry_msgs/Vector3\nfloat64 x\nfloat64 y\nfloat64 z\n"
                + SEP + "MSG: std_msgs/ColorRGBA\nfloat32 r\nfloat32 g\nfloat32 b\nfloat32 a\n")
TF_MESSAGE = ("geometry_msgs/TransformStamped[] transforms\n"
              + SEP + "MSG: geometry_msgs/TransformStamped\nstd_msgs/Header header\nstring child_frame_id\n"
              "Transform transform\n"
              + SEP + "MSG: std_msgs/Header\n" + HEADER
              + SEP + "MSG: builtin_interfaces/Time\n" + TIME
              + SEP + "MSG: geometry_msgs/Transform\nVector3 translation\nQuaternion rotation\n"
              + SEP + "MSG: geometry_msgs/Vector3\nfloat64 x\nfloat64 y\nfloat64 z\n"
              + SEP + "MSG: geometry_msgs/Quaternion\nfloat64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n")
DIAGNOSTIC_ARRAY = ("std_msgs/Header header\ndiagnostic_msgs/DiagnosticStatus[] status\n"
                    + SEP + "MSG: std_msgs/Header\n" + HEADER
                    + SEP + "MSG: builtin_interfaces/Time\n" + TIME
                    + SEP + "MSG: diagnostic_msgs/DiagnosticStatus\nbyte OK=0\nbyte WARN=1\nbyte ERROR=2\nbyte STALE=3\n"
                    "byte level\nstring name\nstring message\nstring hardware_id\ndiagnostic_msgs/KeyValue[] values\n"
                    + SEP + "MSG: diagnostic_msgs/KeyValue\nstring key\nstring value\n")

# a Booster T1's 24 joints (head, arms, waist, legs)
JOINTS = ["head_yaw", "head_pitch"] + ["%s_%s" % (side, j) for side in ("l", "r") for j in (
    "shoulder_pitch", "shoulder_roll", "elbow_pitch", "elbow_yaw")] + ["waist_yaw"] + [
    "%s_%s" % (side, j) for side in ("l", "r") for j in (
        "hip_pitch", "hip_roll", "hip_yaw", "knee_pitch", "ankle_up")] + ["l_toe", "r_toe", "torso_pitch"]
# what the robot's camera sees: a 64×48 JPEG (green field, white ball, blue sky), made once by ImageIO
CAMERA_JPEG = base64.b64decode("/9j/4AAQSkZJRgABAgAAAQABAAD/2wBDAAgGBgcGBQgHBwcJCQgKDBQNDAsLDBkSEw8UHRofHh0aHBwgJC4nICIsIxwcKDcpLDAxNDQ0Hyc5PTgyPC4zNDL/2wBDAQkJCQwLDBgNDRgyIRwhMjIyMjIyMjIyMjIyMjIyMjIyMjIyMjIyMjIyMjIyMjIyMjIyMjIyMjIyMjIyMjIyMjL/wAARCAAwAEADASIAAhEBAxEB/8QAHwAAAQUBAQEBAQEAAAAAAAAAAAECAwQFBgcICQoL/8QAtRAAAgEDAwIEAwUFBAQAAAF9AQIDAAQRBRIhMUEGE1FhByJxFDKBkaEII0KxwRVS0fAkM2JyggkKFhcYGRolJicoKSo0NTY3ODk6Q0RFRkdISUpTVFVWV1hZWmNkZWZnaGlqc3R1dnd4eXqDhIWGh4iJipKTlJWWl5iZmqKjpKWmp6ipqrKztLW2t7i5usLDxMXGx8jJytLT1NXW19jZ2uHi4+Tl5ufo6erx8vP09fb3+Pn6/8QAHwEAAwEBAQEBAQEBAQAAAAAAAAECAwQFBgcICQoL/8QAtREAAgECBAQDBAcFBAQAAQJ3AAECAxEEBSExBhJBUQdhcRMiMoEIFEKRobHBCSMzUvAVYnLRChYkNOEl8RcYGRomJygpKjU2Nzg5OkNERUZHSElKU1RVVldYWVpjZGVmZ2hpanN0dXZ3eHl6goOEhYaHiImKkpOUlZaXmJmaoqOkpaanqKmqsrO0tba3uLm6wsPExcbHyMnK0tPU1dbX2Nna4uPk5ebn6Onq8vP09fb3+Pn6/9oADAMBAAIRAxEAPwBtFYX9oXX/AD1/8dH+FH9oXX/PX/x0f4V1f21h+z/D/M8b28TdorC/tC6/56/+Oj/Cj+0Lr/nr/wCOj/Cj+2sP2f4f5h7eJu0Vhf2hdf8APX/x0f4Uf2hdf89f/HR/hR/bWH7P8P8AMPbxN2isL+0Lr/nr/wCOj/Cj+0Lr/nr/AOOj/Cj+2sP2f4f5h7eJWooor5k5AooooAKK9M+Gnh/TL7S7rULy0juZvOMCrModFUKrZCkdST19uMc50fH/AIb0iLwvPfW1jDbT2zKUa3jCBgzKpDADkc59sfXO6w8nT57nUsLJ0/aXPIqKKKwOUKKKKACiiigDqPCnjW58MRT2/wBmW6tZW3iPfsKvwMhsHggDj2HTnNrxN8QbnxBpn9nxWS2kLsDN+88wuAQQAcDAyM/gPfPG0Vp7Wajy30NlXqKHJfQKKKKzMT//2Q==")
WHITE = {"r": 1.0, "g": 1.0, "b": 1.0, "a": 1.0}
ORANGE = {"r": 1.0, "g": 0.5, "b": 0.0, "a": 1.0}


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
        self.client_channels = {}  # (client id, channel id) -> the channel a client advertised
        self.subscribed = {}  # topic -> subscribers
        self.sent = 0  # messages logged on a subscribed channel

    def on_subscribe(self, client, channel):
        with self.lock:
            self.subscribed[channel.topic] = self.subscribed.get(channel.topic, 0) + 1

    def on_unsubscribe(self, client, channel):
        with self.lock:
            self.subscribed[channel.topic] = self.subscribed.get(channel.topic, 1) - 1

    def log(self, channel, message):
        """Logs on the channel, counting it if a client subscribed to it."""
        with self.lock:
            if self.subscribed.get(channel.topic(), 0) > 0:
                self.sent += 1
        channel.log(message)

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
            self.client_channels[(client.id, channel.id)] = channel
            self.heard.append("client advertised %s (%s)" % (channel.topic, channel.encoding))

    def on_message_data(self, client, client_channel_id, data):
        with self.lock:
            channel = self.client_channels.get((client.id, client_channel_id))
            if channel is not None and channel.encoding == "cdr" and channel.schema:
                try:
                    decode = generate_dynamic(channel.schema_name, channel.schema.decode())[channel.schema_name]
                    text = "(cdr) " + json.dumps(plain(decode(data)), sort_keys=True)
                except Exception as e:  # a message that does not fit its schema: say so, as a robot's log would
                    text = "(cdr, unreadable: %s) %d bytes" % (e, len(data))
            else:
                try:
                    text = data.decode("utf-8")
                except UnicodeDecodeError:
                    text = "%d bytes" % len(data)
            self.heard.append("client published on channel %d: %s" % (client_channel_id, text))

    def take_heard(self):
        with self.lock:
            out, self.heard = self.heard, []
            return out


def plain(value):
    """A message mcap_ros2 decoded (nested namespaces, lists) as plain JSON values."""
    if hasattr(value, "__slots__") or hasattr(value, "__dict__"):
        names = getattr(value, "__slots__", None) or vars(value).keys()
        return {n: plain(getattr(value, n)) for n in names}
    if isinstance(value, (list, tuple)):
        return [plain(v) for v in value]
    if isinstance(value, bytes):
        return list(value)
    return value


TRIGGER_RESPONSE = "bool success\nstring message\n"


def check_service(name):
    """/NAME/check: a std_srvs/srv/Trigger whose request and response are CDR, answered by mcap_ros2's serializer."""
    encode = serialize_dynamic("std_srvs/srv/Trigger_Response", TRIGGER_RESPONSE)["std_srvs/srv/Trigger_Response"]
    request = MessageSchema(encoding="cdr", schema=Schema(name="std_srvs/srv/Trigger_Request", encoding="ros2msg",
                                                          data=b""))
    response = MessageSchema(encoding="cdr", schema=Schema(name="std_srvs/srv/Trigger_Response", encoding="ros2msg",
                                                           data=TRIGGER_RESPONSE.encode()))
    return Service(name="/%s/check" % name, schema=ServiceSchema(name="std_srvs/srv/Trigger", request=request,
                                                                 response=response),
                   handler=lambda req: encode({"success": True, "message": "all joints ready"}))


def no_ball(req):
    raise RuntimeError("no ball in reach")


def stamp(now):
    return {"sec": int(now), "nanosec": int((now % 1) * 1e9)}


def marker(stamp_now, ns, ident, kind, position=(0.0, 0.0), scale=0.1, color=WHITE, points=(), text="", frame="map"):
    return {"header": {"stamp": stamp_now, "frame_id": frame}, "ns": ns, "id": ident, "type": kind, "action": 0,
            "pose": {"position": {"x": position[0], "y": position[1], "z": 0.0},
                     "orientation": {"x": 0.0, "y": 0.0, "z": 0.0, "w": 1.0}},
            "scale": {"x": scale, "y": scale, "z": scale}, "color": color,
            "lifetime": {"sec": 0, "nanosec": 0}, "frame_locked": False,
            "points": [{"x": px, "y": py, "z": 0.0} for px, py in points], "colors": [], "text": text,
            "mesh_resource": "", "mesh_use_embedded_materials": False}


def sim_markers(now, x, y):
    """What the robot's world model draws: where it believes the ball (a sphere), its planned path (a line
    strip), its kick range (a cylinder seen from above: a circle), all in map, and its intention (text) beside
    it, in its own base_link."""
    s = stamp(now)
    ball = (x + 0.8, y * 0.5)
    return [{"header": {"stamp": s, "frame_id": "map"}, "ns": "", "id": 0, "type": 0, "action": 3,
             "pose": {"position": {"x": 0.0, "y": 0.0, "z": 0.0}, "orientation": {"x": 0.0, "y": 0.0, "z": 0.0, "w": 1.0}},
             "scale": {"x": 0.0, "y": 0.0, "z": 0.0}, "color": WHITE, "lifetime": {"sec": 0, "nanosec": 0},
             "frame_locked": False, "points": [], "colors": [], "text": "", "mesh_resource": "",
             "mesh_use_embedded_materials": False},
            marker(s, "ball", 0, 2, position=ball, scale=0.1, color=ORANGE),
            marker(s, "path", 1, 4, points=[(x, y), ((x + ball[0]) / 2, y), ball]),
            marker(s, "kick", 2, 3, position=ball, scale=0.6, color=ORANGE),
            marker(s, "intention", 3, 9, position=(0.0, 0.3), scale=0.2, text="go to ball", frame="base_link")]


def transform(stamp_now, parent, child, x, y, yaw):
    return {"header": {"stamp": stamp_now, "frame_id": parent}, "child_frame_id": child,
            "transform": {"translation": {"x": x, "y": y, "z": 0.0},
                          "rotation": {"x": 0.0, "y": 0.0, "z": math.sin(yaw / 2), "w": math.cos(yaw / 2)}}}


def in_odom(odom, x, y, theta):
    """The pose (x, y, theta) of map in the odometry frame lying at odom = (ox, oy, oyaw) of map."""
    ox, oy, oyaw = odom
    dx, dy = x - ox, y - oy
    c, s = math.cos(oyaw), math.sin(oyaw)
    return c * dx + s * dy, -s * dx + c * dy, theta - oyaw


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--port", type=int, default=8765)
    ap.add_argument("--name", default="ros2-robot")
    ap.add_argument("--rate", type=float, default=20.0, help="pose and joint messages per second")
    ap.add_argument("--seconds", type=float, default=0.0, help="stop after this long (0: never)")
    ap.add_argument("--game-state", default="PLAYING", help="the game state the robot reports on /robot_state")
    ap.add_argument("--camera-jpeg", help="a JPEG file to send as the camera image instead of the built-in 64×48 one")
    ap.add_argument("--camera-hz", type=float, default=5.0, help="camera images per second (at most --rate)")
    ap.add_argument("--centre", default="0,0", help="the centre of the robot's walk on the field, metres: X,Y")
    ap.add_argument("--radius", type=float, default=1.0, help="the size of its walk (0: it turns on the spot)")
    ap.add_argument("--odom", default="0.4,-0.3,0.15",
                    help="where its odometry frame lies in map (its drift): X,Y metres, YAW radians")
    ap.add_argument("--heading", type=float, help="a fixed heading in map, radians (default: it turns with its walk)")
    args = ap.parse_args()
    cx, cy = (float(v) for v in args.centre.split(","))
    odom = tuple(float(v) for v in args.odom.split(","))
    jpeg = CAMERA_JPEG
    if args.camera_jpeg:
        with open(args.camera_jpeg, "rb") as f:
            jpeg = f.read()

    robot = Robot(args.name)
    services = [Service(name="/%s/say" % args.name, schema=ServiceSchema(name="std_srvs/srv/Trigger"),
                        handler=lambda req: json.dumps({"success": True, "message": "said"}).encode()),
                check_service(args.name),
                Service(name="/%s/kick" % args.name, schema=ServiceSchema(name="std_srvs/srv/Trigger"), handler=no_ball)]
    server = foxglove.start_server(name=args.name, host="127.0.0.1", port=args.port, server_listener=robot,
                                   capabilities=[Capability.ClientPublish, Capability.Parameters, Capability.Services],
                                   supported_encodings=["json", "cdr"], services=services)
    log, encode_log = ros2_channel("/rosout", "rcl_interfaces/msg/Log", LOG)
    pose, encode_pose = ros2_channel("/pose", "geometry_msgs/msg/PoseStamped", POSE_STAMPED)
    joints, encode_joints = ros2_channel("/joint_states", "sensor_msgs/msg/JointState", JOINT_STATE)
    state = Channel("/robot_state", message_encoding="json")
    heading = Vector2Channel("/heading")
    camera, encode_camera = ros2_channel("/camera/image/compressed", "sensor_msgs/msg/CompressedImage", COMPRESSED_IMAGE)
    markers, encode_markers = ros2_channel("/markers", "visualization_msgs/msg/MarkerArray", MARKER_ARRAY)
    tf, encode_tf = ros2_channel("/tf", "tf2_msgs/msg/TFMessage", TF_MESSAGE)
    tf_static, encode_tf_static = ros2_channel("/tf_static", "tf2_msgs/msg/TFMessage", TF_MESSAGE)
    diagnostics, encode_diagnostics = ros2_channel("/diagnostics", "diagnostic_msgs/msg/DiagnosticArray",
                                                   DIAGNOSTIC_ARRAY)
    print("listening on port %d" % server.port, flush=True)

    stop = threading.Event()
    signal.signal(signal.SIGTERM, lambda *a: stop.set())
    start = time.time()
    n = 0
    while not stop.is_set() and (args.seconds <= 0 or time.time() - start < args.seconds):
        now = time.time()
        t = now - start
        angle = 0.4 * t
        x, y = cx + 1.2 * args.radius * math.cos(angle), cy + 0.8 * args.radius * math.sin(angle)
        theta = angle + math.pi / 2 if args.heading is None else args.heading
        robot.log(pose, encode_pose({"header": {"stamp": stamp(now), "frame_id": "map"},
                              "pose": {"position": {"x": x, "y": y, "z": 0.0},
                                       "orientation": {"x": 0.0, "y": 0.0, "z": math.sin(theta / 2),
                                                       "w": math.cos(theta / 2)}}}))
        robot.log(joints, encode_joints({"header": {"stamp": stamp(now), "frame_id": ""}, "name": JOINTS,
                                  "position": [0.3 * math.sin(t + i) for i in range(len(JOINTS))],
                                  "velocity": [0.0] * len(JOINTS), "effort": [1.0 + i for i in range(len(JOINTS))]}))
        robot.log(heading, Vector2(x=math.cos(theta), y=math.sin(theta)))
        if n % max(1, int(args.rate / 10)) == 0:
            robot.log(tf, encode_tf({"transforms": [transform(stamp(now), "map", "odom", *odom),
                                                    transform(stamp(now), "odom", "base_link", *in_odom(odom, x, y, theta))]}))
        if n % max(1, int(args.rate / args.camera_hz)) == 0:
            header = {"stamp": stamp(now), "frame_id": "camera"}
            robot.log(camera, encode_camera({"header": header, "format": "jpeg", "data": jpeg}))
        if n % max(1, int(args.rate / 5)) == 0:
            robot.log(markers, encode_markers({"markers": sim_markers(now, x, y)}))
        if n % max(1, int(args.rate)) == 0:
            robot.log(tf_static, encode_tf_static({"transforms": [
                transform(stamp(now), "base_link", "camera", 0.05, 0.0, 0.0)]}))
            battery = max(0.0, 95.0 - t / 60.0)
            robot.log(diagnostics, encode_diagnostics({"header": {"stamp": stamp(now), "frame_id": ""}, "status": [
                {"level": 0, "name": args.name + ": Battery", "message": "discharging", "hardware_id": "bms",
                 "values": [{"key": "Battery", "value": "%.1f" % battery}, {"key": "Voltage", "value": "25.2"}]},
                {"level": 1 if t % 20 > 15 else 0, "name": args.name + ": Motors", "message": "warm",
                 "hardware_id": "joints",
                 "values": [{"key": "Temperature", "value": "%.1f" % (41.5 + math.sin(t))}]}]}))
        for said in robot.take_heard():
            print(said, flush=True)
            robot.log(log, encode_log({"stamp": stamp(now), "level": 20, "name": args.name, "msg": said,
                                "file": "sim_ros2_robot.py", "function": "on_client", "line": 1}))
        if n % max(1, int(args.rate)) == 0:
            robot.log(log, encode_log({"stamp": stamp(now), "level": 20 if n % 3 else 30, "name": args.name + "/behavior",
                                "msg": "walking to (%.2f, %.2f)" % (x, y), "file": "behavior.py",
                                "function": "tick", "line": 42}))
            robot.log(state, {"battery": {"percentage": max(0.0, 95.0 - t / 60.0)}, "temperature": 41.5 + math.sin(t),
                       "game_state": args.game_state})
        n += 1
        stop.wait(max(0.0, start + n / args.rate - time.time()))  # on a grid: the work does not slow the rate
    try:
        print("sent %d" % robot.sent, flush=True)
    except OSError:  # nobody reads our output any more: stopping is all that is left
        pass
    server.stop()


if __name__ == "__main__":
    main()
