package touchline.cli;

import picocli.CommandLine;
import picocli.CommandLine.Command;

/**
 * The headless face of Touchline: every command the UI offers for data, for scripts, CI and
 * match-day recording on a machine without a screen. {@code ./touchline <command>} lands here.
 */
@Command(name = "touchline", mixinStandardHelpOptions = true, versionProvider = VersionProvider.class,
        description = "Pitch-side debug console for RoboCup robot teams.",
        subcommands = {
                ListenCommand.class,
                OptionsCommand.class,
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
                KeysCommand.class,
        })
public final class Main implements Runnable {

    public static void main(String[] args) {
        System.exit(execute(args, new java.io.PrintWriter(System.err, true)));
    }

    /**
     * Runs one command and returns its exit code. A {@link StartFailure} (port in use, no
     * display, robot side not built) prints its one sentence to {@code err}, no stack trace.
     */
    static int execute(String[] args, java.io.PrintWriter err) {
        CommandLine cli = new CommandLine(new Main());
        cli.setErr(err);
        cli.setExecutionExceptionHandler((e, line, parsed) -> {
            for (Throwable c = e; c != null; c = c.getCause()) {
                if (c instanceof StartFailure f) {
                    return say(err, line, f);
                }
            }
            if (StartFailure.addressInUse(e)) { // a command that binds without UdpOptions.startConsole
                return say(err, line, new StartFailure("A UDP port this command needs is already in use (another "
                        + "Touchline or a team tool is listening there): close that program, or start with --port "
                        + "and a free port.", StartFailure.PORT_IN_USE));
            }
            throw e;
        });
        return cli.execute(args);
    }

    private static int say(java.io.PrintWriter err, CommandLine line, StartFailure f) {
        err.println("touchline " + line.getCommandName() + ": " + f.getMessage());
        err.flush();
        return f.exitCode();
    }

    @Override
    public void run() {
        new CommandLine(this).usage(System.out);
    }
}
