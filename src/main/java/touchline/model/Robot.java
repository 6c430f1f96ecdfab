package touchline.model;

import touchline.proto.Fumanoid;
import touchline.security.Authenticity;
import touchline.transport.Envelope;
import touchline.transport.Origin;

import java.net.InetSocketAddress;
import java.util.Optional;

/** The registry's mutable record of one robot. Guarded by the registry's lock. */
final class Robot {

    final int id;
    final Origin origin;
    final long firstSeenMicros;
    long lastSeenMicros;
    boolean online;
    long packets;
    long malformed;
    long addressChanges;
    InetSocketAddress address;
    final RateWindow rate = new RateWindow();
    Fumanoid.Status status = Fumanoid.Status.getDefaultInstance();
    Authenticity auth = Authenticity.NOT_CHECKED;
    long verified;
    long unverified;
    long forged;
    String lastForgery = "";
    int bootId;
    boolean hasBootId;
    /** A robot behind a Foxglove bridge: named by the console, its facts read from its ROS 2 messages. */
    boolean bridged;
    String givenName;

    Robot(int id, Origin origin, long firstSeenMicros) {
        this.id = id;
        this.origin = origin;
        this.firstSeenMicros = firstSeenMicros;
    }

    /** @return a note when the robot's address changed, else null */
    private static final RosDiagnostics DIAGNOSTICS = new RosDiagnostics();
    /** The hottest temperature its ROS 2 messages last reported, °C; NaN for none. */
    private double temperature = Double.NaN;

    /** Its TF tree and its latest pose with the frame it was given in (a ROS 2 robot's; null: none yet). */
    private FrameTree frames = FrameTree.EMPTY;
    private RosReadings.FramedPose framedPose;

    String take(Envelope e, RosReadings readings) {
        if (e.ros() != null) {
            frames = frames.with(readings.links(e.ros()));
            var posed = readings.framedPose(e.kind(), e.ros());
            framedPose = posed.orElse(framedPose);
            status = read(status, e.kind(), e.ros(), readings, posed.map(p -> new RobotFrames(frames, p).fieldPose()));
            temperature = DIAGNOSTICS.temperature(e.ros()).orElse(temperature);
        }
        return take(e);
    }

    /** Its frames, for a view that draws it in a frame of its choice; null for a robot that told none. */
    RobotFrames frames() {
        return framedPose == null && frames == FrameTree.EMPTY ? null : new RobotFrames(frames, framedPose);
    }

    /**
     * The robot's status with what a ROS 2 message says of it (pose, battery, game state) put in; its
     * pose in {@value RobotFrames#FIELD} when its TF tree leads there, else as given.
     */
    private static Fumanoid.Status read(Fumanoid.Status s, String topic, touchline.protocol.ros2.RosMessage m,
                                        RosReadings readings, Optional<Transform2D> pose) {
        Fumanoid.Status.Builder b = null;
        if (pose.isPresent()) {
            b = s.toBuilder();
            // ROS 2 speaks metres (REP 103), the field and the small robots millimetres
            b.getRobotPositionBuilder().setX((float) (pose.get().x() * 1000)).setY((float) (pose.get().y() * 1000))
                    .setTheta((float) pose.get().yaw());
        }
        var battery = readings.batteryPercent(topic, m);
        if (battery.isPresent() && (!s.hasBatteryPercent() || s.getBatteryPercent() != battery.get())) {
            b = b == null ? s.toBuilder() : b;
            b.setBatteryPercent(battery.get());
        }
        var game = readings.gameState(topic, m);
        if (game.isPresent() && !game.get().equals(s.getGameState())) {
            b = b == null ? s.toBuilder() : b;
            b.setGameState(game.get());
        }
        return b == null ? s : b.build();
    }

    String take(Envelope e) {
        String note = null;
        if (address != null && e.peer() != null && !address.equals(e.peer())) {
            addressChanges++;
            note = "robot " + id + " moved from " + address + " to " + e.peer();
        }
        if (e.peer() != null) {
            address = e.peer();
        }
        lastSeenMicros = Math.max(lastSeenMicros, e.timeMicros());
        packets++;
        rate.add(e.timeMicros(), e.size());
        if (e.authenticity() == Authenticity.VERIFIED) {
            verified++;
            auth = Authenticity.VERIFIED;
        } else if (e.authenticity() == Authenticity.UNVERIFIED || e.authenticity() == Authenticity.UNTAGGED) {
            unverified++;
            auth = e.authenticity();
        }
        Fumanoid.Status reported = e.extension(Fumanoid.status);
        if (reported != null) {
            status = reported;
            if (reported.hasAuth() && reported.getAuth().hasBootId()) {
                int boot = reported.getAuth().getBootId();
                if (hasBootId && boot != bootId && note == null) {
                    note = "robot " + id + " restarted: counter reset, accepted";
                }
                bootId = boot;
                hasBootId = true;
            }
        }
        return note;
    }

    /** A datagram claiming this robot was dropped as forged; true when it is worth a note (1st, 2nd, 4th, 8th...). */
    boolean forgery(Envelope e) {
        forged++;
        lastForgery = e.peerText() + ": " + e.error();
        if (packets == 0) {
            auth = Authenticity.FORGED; // nothing genuine from this id yet
        }
        return (forged & (forged - 1)) == 0;
    }

    RobotSnapshot snapshot(long now) {
        Fumanoid.Status s = status;
        boolean hasPosition = s.hasRobotPosition();
        return new RobotSnapshot(id, s.hasRobotName() ? s.getRobotName() : givenName != null ? givenName : "robot " + id,
                s.hasTeamID() ? s.getTeamID() : RobotSnapshot.UNKNOWN,
                s.hasBatteryPercent() ? s.getBatteryPercent() : RobotSnapshot.UNKNOWN,
                s.getActiveRole(), s.getCurrentState(), s.getGameState(),
                s.getRobotPosition().getX(), s.getRobotPosition().getY(), s.getRobotPosition().getTheta(), hasPosition,
                s.getTimeOnline(), firstSeenMicros, lastSeenMicros, online, packets,
                rate.perSecond(now), rate.bytesPerSecond(now), malformed, addressChanges, address, origin,
                new RobotAuth(auth, verified, unverified, forged, lastForgery, s.hasAuth() ? s.getAuth() : null),
                s.getGcOtherSource(), temperature);
    }
}
