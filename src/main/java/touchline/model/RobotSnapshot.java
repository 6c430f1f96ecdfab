package touchline.model;

import touchline.transport.Origin;

import java.net.InetSocketAddress;

/**
 * One robot as the views show it, frozen at one moment. Times are microseconds since the
 * epoch; {@code timeOnlineSeconds} is what the robot reports, {@code firstSeenMicros} what the
 * console saw. A replayed robot ({@code origin} REPLAY) is a different robot from the live
 * one with the same ID; views say which is which ({@link #label()}). {@code gcOtherSource} is
 * what the robot reports of GameController packets from another source than the one it follows;
 * {@code temperature} the hottest a ROS 2 robot reports (°C, NaN for none: {@link RosDiagnostics}).
 */
public record RobotSnapshot(int id, String name, int teamId, int batteryPercent, String role, String state,
                            String gameState, double x, double y, double theta, boolean hasPosition,
                            long timeOnlineSeconds, long firstSeenMicros, long lastSeenMicros, boolean online,
                            long packets, double packetsPerSecond, double bytesPerSecond, long malformed,
                            long addressChanges, InetSocketAddress address, Origin origin, RobotAuth auth,
                            long gcOtherSource, double temperature) {

    public static final int UNKNOWN = -1;

    /** A robot whose authenticity nobody checked (tests, views without a link). */
    public RobotSnapshot(int id, String name, int teamId, int batteryPercent, String role, String state,
                         String gameState, double x, double y, double theta, boolean hasPosition,
                         long timeOnlineSeconds, long firstSeenMicros, long lastSeenMicros, boolean online,
                         long packets, double packetsPerSecond, double bytesPerSecond, long malformed,
                         long addressChanges, InetSocketAddress address, Origin origin) {
        this(id, name, teamId, batteryPercent, role, state, gameState, x, y, theta, hasPosition, timeOnlineSeconds,
                firstSeenMicros, lastSeenMicros, online, packets, packetsPerSecond, bytesPerSecond, malformed,
                addressChanges, address, origin, RobotAuth.NONE, 0);
    }

    /** A robot that reports no temperature (every small robot). */
    public RobotSnapshot(int id, String name, int teamId, int batteryPercent, String role, String state,
                         String gameState, double x, double y, double theta, boolean hasPosition,
                         long timeOnlineSeconds, long firstSeenMicros, long lastSeenMicros, boolean online,
                         long packets, double packetsPerSecond, double bytesPerSecond, long malformed,
                         long addressChanges, InetSocketAddress address, Origin origin, RobotAuth auth,
                         long gcOtherSource) {
        this(id, name, teamId, batteryPercent, role, state, gameState, x, y, theta, hasPosition, timeOnlineSeconds,
                firstSeenMicros, lastSeenMicros, online, packets, packetsPerSecond, bytesPerSecond, malformed,
                addressChanges, address, origin, auth, gcOtherSource, Double.NaN);
    }

    /** The game state as views show it, with the other GameController the robot did not believe, if any. */
    public String gameStateShown() {
        return gcOtherSource == 0 ? gameState
                : gameState + " (" + gcOtherSource + " from another GameController, not believed)";
    }

    public boolean replayed() {
        return origin == Origin.REPLAY;
    }

    /** The robot's name as views show it: {@code "robot 3"}, or {@code "robot 3 (replay)"} for a replayed one. */
    public String label() {
        return replayed() ? name + " (replay)" : name;
    }
}
