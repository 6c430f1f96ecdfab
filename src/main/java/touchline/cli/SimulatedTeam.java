package touchline.cli;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * Simulated robots ({@code touchline-robot} from the robot-side build) sending to a console on
 * loopback, for the screenshot and benchmark commands. Their output goes to a log file each.
 */
public final class SimulatedTeam implements AutoCloseable {

    private final List<Process> processes = new ArrayList<>();

    /** Starts robots 1..n; fails with one sentence when the binary was not built. */
    public static SimulatedTeam start(int n, int consolePort, List<String> extra) throws IOException, StartFailure {
        RobotSideBinaries binaries = new RobotSideBinaries();
        java.util.Optional<String> missing = binaries.missing("touchline-robot");
        if (missing.isPresent()) {
            throw StartFailure.robotSideMissing(missing.get());
        }
        Path bin = binaries.of("touchline-robot");
        SimulatedTeam team = new SimulatedTeam();
        Path logs = Files.createTempDirectory("touchline-team");
        for (int i = 1; i <= n; i++) {
            List<String> cmd = new ArrayList<>(List.of(bin.toString(), "--id", Integer.toString(i), "--team", "13",
                    "--console", "127.0.0.1:" + consolePort, "--port", "0"));
            cmd.addAll(extra);
            team.processes.add(new ProcessBuilder(cmd).redirectErrorStream(true)
                    .redirectOutput(logs.resolve("robot-" + i + ".log").toFile()).start());
        }
        return team;
    }

    @Override
    public void close() throws InterruptedException {
        for (Process p : processes) {
            p.destroy();
        }
        for (Process p : processes) {
            if (!p.waitFor(3, TimeUnit.SECONDS)) {
                p.destroyForcibly();
            }
        }
    }
}
