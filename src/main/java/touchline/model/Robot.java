package touchline.model;

import touchline.proto.Fumanoid;
import touchline.transport.Envelope;
import touchline.transport.Origin;

import java.net.InetSocketAddress;

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

    Robot(int id, Origin origin, long firstSeenMicros) {
        this.id = id;
        this.origin = origin;
        this.firstSeenMicros = firstSeenMicros;
    }

    /** @return a note when the robot's address changed, else null */
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
        Fumanoid.Status reported = e.extension(Fumanoid.status);
        if (reported != null) {
            status = reported;
        }
        return note;
    }

    RobotSnapshot snapshot(long now) {
        Fumanoid.Status s = status;
        boolean hasPosition = s.hasRobotPosition();
        return new RobotSnapshot(id, s.hasRobotName() ? s.getRobotName() : "robot " + id,
                s.hasTeamID() ? s.getTeamID() : RobotSnapshot.UNKNOWN,
                s.hasBatteryPercent() ? s.getBatteryPercent() : RobotSnapshot.UNKNOWN,
                s.getActiveRole(), s.getCurrentState(), s.getGameState(),
                s.getRobotPosition().getX(), s.getRobotPosition().getY(), s.getRobotPosition().getTheta(), hasPosition,
                s.getTimeOnline(), firstSeenMicros, lastSeenMicros, online, packets,
                rate.perSecond(now), rate.bytesPerSecond(now), malformed, addressChanges, address, origin);
    }
}
