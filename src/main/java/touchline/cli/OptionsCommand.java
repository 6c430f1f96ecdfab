package touchline.cli;

import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import touchline.app.Console;
import touchline.model.OptionState;
import touchline.model.RobotOptions;
import touchline.transport.SendResult;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.function.BooleanSupplier;

/**
 * Drives a robot's debug options from a script: waits for the robot and its option list,
 * switches options on or off, waits until the robot's data confirms it, prints the list.
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

    @Option(names = "--timeout", description = "seconds to wait for the robot (default ${DEFAULT-VALUE})", defaultValue = "10")
    long timeoutSeconds;

    @Mixin
    UdpOptions udp;

    @picocli.CommandLine.Spec
    picocli.CommandLine.Model.CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        try (Console console = udp.startConsole()) {
            new FirstListenLines(spec.commandLine().getErr(), "options").follow(console.matchMode());
            long deadline = System.nanoTime() + timeoutSeconds * 1_000_000_000L;
            if (!await(deadline, () -> console.options().options(robot).listReceived())) {
                System.err.println(console.robots().robot(robot).isPresent()
                        ? "robot " + robot + " did not send its option list within " + timeoutSeconds + " s"
                        : "robot " + robot + " was not seen within " + timeoutSeconds + " s (is it sending to port "
                        + console.port() + "?)");
                return 2;
            }
            // a console that just opened the GameController port listens for one first (match mode):
            // the requests wait for that, or for play to be heard, instead of being held for it
            console.awaitFirstListen(0, java.time.Duration.ofNanos(Math.max(0, deadline - System.nanoTime())));
            int status = 0;
            for (String name : on) {
                status |= apply(console, name, true);
            }
            for (String name : off) {
                status |= apply(console, name, false);
            }
            if (status != 0) {
                return status;
            }
            boolean confirmed = await(deadline, () -> {
                RobotOptions o = console.options().options(robot);
                return on.stream().allMatch(n -> o.option(n).map(OptionState::streaming).orElse(false));
            });
            print(console.options().options(robot));
            if (!confirmed) {
                System.err.println("the robot did not start streaming every requested option within " + timeoutSeconds + " s");
                return 3;
            }
            return 0;
        }
    }

    private int apply(Console console, String name, boolean enable) {
        RobotOptions options = console.options().options(robot);
        if (options.option(name).isEmpty()) {
            System.err.println("robot " + robot + " offers no option '" + name + "'");
            return 1;
        }
        // --off names the option: switched off whoever switched it on (a new console wants nothing)
        SendResult r = enable ? console.setOption(robot, name, true) : console.switchOptionOff(robot, name);
        if (!r.isSent()) {
            System.err.println(name + ": " + r.outcome().name().toLowerCase() + ": " + r.reason());
            return 4;
        }
        return 0;
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

    private void print(RobotOptions options) {
        System.out.printf("robot %d: %d options%n", options.robotId(), options.options().size());
        for (OptionState o : options.options()) {
            System.out.printf("  [%s] %-16s %-20s %s%s%n", o.wanted() ? "x" : " ", o.name(), o.kindName(),
                    o.description(), o.streaming() ? "  (streaming)" : "");
        }
    }
}
