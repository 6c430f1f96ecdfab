package touchline.cli;

import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import touchline.app.Console;
import touchline.transport.Envelope;

import java.io.PrintStream;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

/** Prints the robots seen and every decoded message as text, until stopped. */
@Command(name = "listen", mixinStandardHelpOptions = true,
        description = "Listen for robots: print every message as text and a robot table every few seconds.")
final class ListenCommand implements java.util.concurrent.Callable<Integer> {

    @Mixin
    UdpOptions udp;

    @Mixin
    TeamBudgetOptions budget;

    @Mixin
    RemoteOptions remote;

    @Option(names = "--quiet", description = "print only the robot table, not every message")
    boolean quiet;

    @Option(names = "--seconds", description = "stop after this many seconds (0 = run until Ctrl+C)", defaultValue = "0")
    long seconds;

    @Option(names = "--table-every", description = "seconds between robot tables (default ${DEFAULT-VALUE})", defaultValue = "2")
    long tableEvery;

    @picocli.CommandLine.Spec
    picocli.CommandLine.Model.CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        PrintStream out = new PrintStream(new java.io.FileOutputStream(java.io.FileDescriptor.out), true);
        EnvelopeLine lines = new EnvelopeLine();
        MonitorTable monitorTable = new MonitorTable();
        CountDownLatch stop = new CountDownLatch(1);
        Runtime.getRuntime().addShutdownHook(new Thread(stop::countDown));
        try (Console console = remote.remote() ? remote.startViewing() : new Console(udp.config())) {
            RobotTable table = new RobotTable(console.field().matchRule()::reading);
            if (!quiet) {
                console.field().bus().subscribe((Envelope e) -> {
                    synchronized (out) {
                        out.println(lines.format(e));
                    }
                });
            }
            if (!remote.remote()) {
                udp.start(console);
                new FirstListenLines(spec.commandLine().getErr(), "listen").follow(console.referee().matchMode());
            }
            var guard = budget.guard(console.teamBudget(), udp.bind);
            System.err.println(console.remote().status().map(r -> r.describe()).orElse("listening on UDP port "
                    + console.field().port() + " (transport: " + console.field().transportDescription() + ")")
                    + guard.map(g -> ", team " + g.team() + "'s messages under " + g.profile().name()).orElse(""));
            String[] lastRemote = {""};
            long deadline = seconds > 0 ? System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds) : Long.MAX_VALUE;
            while (System.nanoTime() < deadline) {
                if (stop.await(Math.min(TimeUnit.SECONDS.toNanos(tableEvery), Math.max(1, deadline - System.nanoTime())),
                        TimeUnit.NANOSECONDS)) {
                    break;
                }
                console.remote().status().map(r -> r.describe()).filter(d -> !d.equals(lastRemote[0])).ifPresent(d -> {
                    lastRemote[0] = d;
                    System.err.println(d);
                });
                synchronized (out) {
                    table.print(out, console.field().robots().robots(), console.field().robots().sources(), console.field().robots().notes());
                    monitorTable.print(out, console.referee().monitorReport(console.field().clock().nowMicros() / 1000));
                    out.println(console.referee().sources().describe());
                    String gcWarning = console.referee().sources().warning();
                    if (!gcWarning.isEmpty()) {
                        out.println(gcWarning);
                    }
                    guard.ifPresent(g -> out.println(g.snapshot().describe()));
                    out.flush();
                }
            }
            synchronized (out) {
                table.print(out, console.field().robots().robots(), console.field().robots().sources(), console.field().robots().notes());
                out.flush();
            }
        }
        return 0;
    }
}
