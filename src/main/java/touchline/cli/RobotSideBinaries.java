package touchline.cli;

import java.nio.file.Path;

/**
 * Where the robot-side build put its programs: {@code -Dtouchline.robotside.bin} (the launcher
 * sets it), else {@code robot-side/build/bin} under the working directory.
 */
public final class RobotSideBinaries {

    private final Path dir = Path.of(System.getProperty("touchline.robotside.bin", "robot-side/build/bin"));

    /** e.g. {@code touchline-robot}, {@code touchline-nao-sim}, {@code touchline-blast} */
    public Path of(String program) {
        return dir.resolve(program);
    }
}
