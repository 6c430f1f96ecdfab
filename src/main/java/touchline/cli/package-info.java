/**
 * The headless face: {@code Main} and one picocli command per verb ({@code ListenCommand}, {@code RecordCommand},
 * {@code ReplayCommand}, {@code ExportCommand}, {@code GcCommand}, {@code NaoCommand}, {@code ServeCommand},
 * {@code KeysCommand}, {@code ConsoleCommand} which opens the window, ...), their shared options ({@code
 * UdpOptions}, {@code KeyChoice}, {@code TeamBudgetOptions}) and one text line per envelope ({@code
 * EnvelopeLine}). A command that cannot start says why in one sentence ({@code StartFailure}).
 * A command that runs a console makes it (it is its process's entry point) and hands its helpers the services
 * they need; {@code gc} uses a {@code Referee} without a console. Where the robot-side programs are is
 * {@code RobotSideBinaries}'s to say ({@code -Dtouchline.robotside.bin}, else {@code robot-side/build/bin}).
 * <p>
 * May depend on: every layer below, and ui for the commands that open the window; nothing uses it.
 */
package touchline.cli;
