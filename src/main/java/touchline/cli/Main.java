package touchline.cli;

import picocli.CommandLine;
import picocli.CommandLine.Command;

/**
 * The headless face of Touchline: every command the UI offers for data, for scripts, CI and
 * match-day recording on a machine without a screen. {@code ./touchline <command>} lands here.
 */
@Command(name = "touchline", mixinStandardHelpOptions = true, version = "Touchline 0.1",
        description = "Pitch-side debug console for RoboCup robot teams.",
        subcommands = {
                ListenCommand.class,
                OptionsCommand.class,
                BenchCommand.class,
                StreamCommand.class,
                ConsoleCommand.class,
                ScreenshotsCommand.class,
                RecordCommand.class,
                RecoverCommand.class,
                ReplayCommand.class,
                ExportCommand.class,
                GcCommand.class,
                NaoCommand.class,
                ServeCommand.class,
        })
public final class Main implements Runnable {

    public static void main(String[] args) {
        System.exit(new CommandLine(new Main()).execute(args));
    }

    @Override
    public void run() {
        new CommandLine(this).usage(System.out);
    }
}
