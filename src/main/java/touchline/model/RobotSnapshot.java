package touchline.model;

import java.net.InetSocketAddress;

/**
 * One robot as the views show it, frozen at one moment. Times are microseconds since the
 * epoch; {@code timeOnlineSeconds} is what the robot reports, {@code firstSeenMicros} what the
 * console saw.
 */
public record RobotSnapshot(int id, String name, int teamId, int batteryPercent, String role, String state,
                            String gameState, double x, double y, double theta, boolean hasPosition,
                            long timeOnlineSeconds, long firstSeenMicros, long lastSeenMicros, boolean online,
                            long packets, double packetsPerSecond, double bytesPerSecond, long malformed,
                            long addressChanges, InetSocketAddress address) {

    public static final int UNKNOWN = -1;
}
