package touchline.app;

import touchline.model.RobotPresence;
import touchline.model.RobotSnapshot;
import touchline.transport.MicrosClock;

import java.util.Optional;
import java.util.function.Supplier;

/**
 * Waiting for a live robot ({@link LiveField#waitForRobot}) without polling: the robot registry
 * signals each robot that comes online (a presence listener), the console's tick signals that
 * its clock moved on, and a waiter looks again only then, with its deadline on the console's
 * clock (a fake clock in tests decides when the wait ends).
 */
final class RobotWaits implements RobotPresence {

    private final MicrosClock clock;
    private final Object signal = new Object();

    RobotWaits(MicrosClock clock) {
        this.clock = clock;
    }

    /**
     * Waits until {@code seen} gives a robot, or the console's clock reaches
     * {@code timeoutMicros} from now; what {@code seen} gives last.
     */
    Optional<RobotSnapshot> await(Supplier<Optional<RobotSnapshot>> seen, long timeoutMicros) throws InterruptedException {
        long deadline = clock.nowMicros() + timeoutMicros;
        synchronized (signal) {
            Optional<RobotSnapshot> robot = seen.get();
            for (long left = deadline - clock.nowMicros(); robot.isEmpty() && left > 0;
                    left = deadline - clock.nowMicros()) {
                // woken by a robot coming online or the console's tick; the bound is the real clock's part
                signal.wait(Math.max(1, left / 1000));
                robot = seen.get();
            }
            return robot;
        }
    }

    @Override
    public void cameOnline(int robotId, boolean firstTime) {
        wake();
    }

    @Override
    public void wentOffline(int robotId) {
        // a robot going offline is no robot appearing
    }

    /** The console's tick: its clock moved on, so a waiter past its deadline stops waiting. */
    void tick() {
        wake();
    }

    private void wake() {
        synchronized (signal) {
            signal.notifyAll();
        }
    }
}
