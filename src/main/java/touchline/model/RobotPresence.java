package touchline.model;

/** Told when a robot appears, comes back after being offline, or goes offline. */
public interface RobotPresence {

    /** @param firstTime true on the robot's first packet ever, false when it comes back */
    void cameOnline(int robotId, boolean firstTime);

    void wentOffline(int robotId);
}
