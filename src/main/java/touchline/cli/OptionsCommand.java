package touchline.cli;

import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import touchline.app.Console;
import touchline.app.OptionSwitches;
import touchline.model.OptionState;
import touchline.model.RobotOptions;
import touchline.transport.SendResult;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.function.BooleanSupplier;

/**
 * Drives a robot's debug options from a script: waits for the robot and its option list,
 * switches options on or off, waits until the robot's data confirms it, prints the list. With
 * {@code --connect URL} it does so through a Touchline that already holds the robots' port
 * ({@code touchline serve}, or a window serving to viewers) on this machine: that console
 * switches the option, through its match mode, and this one watches its stream.
 */
@Command(name = "options", mixinStandardHelpOptions = true,
        description = "Show a robot's debug options and switch them on or off.")
final class OptionsCommand implements Callable<Integer> {

    @Parameters(index = "0", description = "robot ID")
    int robot;

    @Option(names = "--on", description = "option to switch on (repeatable)")
    List<String> on = new ArrayList<>();

    @Option(names = "--off", description = "option to switch off (repeatable)")
    List<String> off = new ArrayList<>();

    @Option(names = "--match", paramLabel = "NAME",
            description = "option the robot puts into its match digest during play, in this order (repeatable;"
                    + " replaces the robot's choice; sent outside play only)")
    List<String> match = new ArrayList<>();

    @Option(names = "--no-match", description = "no match items: the robot sends its Status alone during play")
    boolean noMatch;

    @Option(names = "--timeout", description = "seconds to wait for the robot (default ${DEFAULT-VALUE})", defaultValue = "10")
    long timeoutSeconds;

    @Mixin
    UdpOptions udp;

    @Mixin
    RemoteOptions remote;

    @picocli.CommandLine.Spec
    picocli.CommandLine.Model.CommandSpec spec;

    private java.io.PrintWriter err;

    @Override
    public Integer call() throws Exception {
        err = spec.commandLine().getErr();
        try {
            return run();
        } finally {
            err.flush();
        }
    }

    private int run() throws Exception {
        try (Console console = remote.remote() ? remote.startViewing() : startOnThePort()) {
            if (!remote.remote()) {
                new FirstListenLines(spec.commandLine().getErr(), "options").follow(console.referee().matchMode());
            }
            long deadline = System.nanoTime() + timeoutSeconds * 1_000_000_000L;
            // through a serving console, a robot that reports play sends no option list (and the serving
            // console, which may have started serving in play, asks for none): the switch is asked at once and
            // the serving console's match mode answers (held)
            boolean askOnly = remote.remote() && !(on.isEmpty() && off.isEmpty());
            if (!await(deadline, () -> console.field().options().options(robot).listReceived()
                    || askOnly && console.field().robots().robot(robot)
                    .map(r -> touchline.protocol.gamecontroller.GameControlData.isPlay(
                            touchline.protocol.gamecontroller.GameControlData.stateCode(r.gameState()))).orElse(false))) {
                err.println(console.field().robots().robot(robot).isPresent()
                        ? "robot " + robot + " did not send its option list within " + timeoutSeconds + " s"
                        : remote.remote() ? "robot " + robot + " was not seen within " + timeoutSeconds + " s through "
                        + remote.connect + " (" + console.remote().status().map(Object::toString).orElse("") + ")"
                        : "robot " + robot + " was not seen within " + timeoutSeconds + " s (is it sending to port "
                        + console.field().port() + "?)");
                return 2;
            }
            // a console that just opened the GameController port listens for one first (match mode):
            // the requests wait for that, or for play to be heard, instead of being held for it
            if (!remote.remote()) { // through a serving console: its match mode decides
                console.referee().awaitFirstListen(0, java.time.Duration.ofNanos(Math.max(0, deadline - System.nanoTime())));
            }
            int status = 0;
            if (!match.isEmpty() || noMatch) {
                status |= choose(console.optionSwitches().options());
            }
            for (String name : on) {
                status |= apply(console.optionSwitches(), name, true, deadline);
            }
            for (String name : off) {
                status |= apply(console.optionSwitches(), name, false, deadline);
            }
            if (status != 0) {
                return status;
            }
            boolean confirmed = await(deadline, () -> {
                RobotOptions o = console.field().options().options(robot);
                return on.stream().allMatch(n -> o.option(n).map(OptionState::streaming).orElse(false))
                        && o.options().stream().allMatch(OptionState::matchConfirmed);
            });
            print(console.optionSwitches(), console.field().options().options(robot));
            if (!confirmed) {
                err.println("the robot did not start streaming every requested option, or confirm its match items,"
                        + " within " + timeoutSeconds + " s");
                return 3;
            }
            return 0;
        }
    }

    private int apply(OptionSwitches switches, String name, boolean enable, long deadlineNanos) throws InterruptedException {
        RobotOptions options = switches.options().options(robot);
        if (options.option(name).isEmpty() && (options.listReceived() || !remote.remote())) {
            err.println("robot " + robot + " offers no option '" + name + "'");
            return 1;
        }
        // --off names the option: switched off whoever switched it on (a new console wants nothing)
        SendResult r = remote.remote() ? askServer(switches, name, enable, deadlineNanos)
                : switches.switchAsAsked(robot, name, enable);
        if (!r.isSent()) {
            err.println(name + ": " + r.outcome().name().toLowerCase() + ": " + r.reason());
            return 4;
        }
        return 0;
    }

    /** Sends the robot its match items (the digest's content in play); 1 unknown name, 4 held or not sent. */
    private int choose(touchline.model.DebugOptionSession session) {
        if (remote.remote()) {
            err.println("--match: choose match items on the serving console (its Debug options view), not through it");
            return 1;
        }
        RobotOptions options = session.options(robot);
        for (String name : match) {
            if (options.option(name).isEmpty()) {
                err.println("robot " + robot + " offers no option '" + name + "'");
                return 1;
            }
        }
        SendResult r = session.setMatchItems(robot, match);
        if (r.outcome() != SendResult.Outcome.SENT) {
            err.println("match items: " + r.outcome().name().toLowerCase() + ": " + r.reason());
            return 4;
        }
        return 0;
    }

    /** The robots' port held by another program: the sentence says how to go through a serving Touchline. */
    private Console startOnThePort() throws InterruptedException, StartFailure {
        try {
            return udp.startConsole();
        } catch (StartFailure e) {
            if (e.exitCode() != StartFailure.PORT_IN_USE) {
                throw e;
            }
            throw new StartFailure(e.getMessage() + " A Touchline serving there (touchline serve, or a window serving"
                    + " to viewers) switches options for this machine: options " + robot
                    + " --connect ws://127.0.0.1:8765/ …", e.exitCode());
        }
    }

    private SendResult askServer(OptionSwitches switches, String name, boolean enable, long deadlineNanos)
            throws InterruptedException {
        try {
            return switches.switchRemotely(robot, name, enable)
                    .get(Math.max(1, deadlineNanos - System.nanoTime()), java.util.concurrent.TimeUnit.NANOSECONDS);
        } catch (java.util.concurrent.TimeoutException e) {
            return SendResult.failed("no answer from " + remote.connect + " within " + timeoutSeconds + " s");
        } catch (java.util.concurrent.ExecutionException e) {
            return SendResult.failed(String.valueOf(e.getCause()));
        }
    }

    private static boolean await(long deadlineNanos, BooleanSupplier condition) throws InterruptedException {
        while (System.nanoTime() < deadlineNanos) {
            if (condition.getAsBoolean()) {
                return true;
            }
            Thread.sleep(20);
        }
        return condition.getAsBoolean();
    }

    private void print(OptionSwitches switches, RobotOptions options) {
        System.out.printf("robot %d: %d options%n", options.robotId(), options.options().size());
        for (OptionState o : options.options()) {
            System.out.printf("  [%s] %-16s %-20s %s%s%s%n", switches.shownOn(o) ? "x" : " ", o.name(), o.kindName(),
                    o.description(), o.streaming() ? "  (streaming)" : "", matchText(o));
        }
    }

    /** "  (in the game: 2nd)", with "asked, not confirmed yet" until the robot's list shows the place. */
    static String matchText(OptionState o) {
        if (o.matchRank() == 0 && o.matchRankOnRobot() == 0) {
            return "";
        }
        if (o.matchConfirmed()) {
            return "  (in the game: #" + o.matchRank() + ")";
        }
        return o.matchRank() == 0 ? "  (in the game on the robot: #" + o.matchRankOnRobot() + ", out asked)"
                : "  (in the game: #" + o.matchRank() + " asked, not confirmed yet)";
    }
}
