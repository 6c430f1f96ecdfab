package touchline.testing;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * The simulated ROS 2 robot ({@code robot-side/ros2/sim_ros2_robot.py}): a Foxglove SDK server
 * (foxglove.sdk.v1) whose CDR bytes come from {@code mcap_ros2}'s serializer, run as a real
 * process on loopback. Skips (or under CI fails) when python3 lacks {@code foxglove} or
 * {@code mcap_ros2}.
 */
public final class SimulatedRos2Robot implements AutoCloseable {

    public static final String SCRIPT = "robot-side/ros2/sim_ros2_robot.py";

    private final RobotProcess process;

    /** Starts one named {@code name}; {@code extra}: more of the script's options (e.g. {@code --game-state READY}). */
    public SimulatedRos2Robot(String name, String... extra) throws IOException {
        Requirement.require(pythonHas("foxglove, mcap_ros2"),
                "python3 cannot import foxglove and mcap_ros2 (./touchline installs them: pip install foxglove-sdk "
                        + "mcap-ros2-support)");
        List<String> cmd = new ArrayList<>(List.of("python3", SCRIPT, "--port", "0", "--name", name));
        cmd.addAll(List.of(extra));
        this.process = RobotProcess.of(cmd).start();
    }

    public String url() {
        return "ws://127.0.0.1:" + process.port() + "/";
    }

    public int port() {
        return process.port();
    }

    /** What clients sent the robot (parameter sets, client messages), one line each, as it printed them. */
    public String heard() {
        return process.stdout();
    }

    private static boolean pythonHas(String imports) {
        try {
            Process p = new ProcessBuilder("python3", "-c", "import " + imports).redirectErrorStream(true).start();
            return p.waitFor(30, TimeUnit.SECONDS) && p.exitValue() == 0;
        } catch (IOException | InterruptedException e) {
            return false;
        }
    }

    @Override
    public void close() throws InterruptedException {
        process.close();
    }
}
