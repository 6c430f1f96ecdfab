package touchline.bench.record;

import picocli.CommandLine;
import touchline.app.Console;
import touchline.app.ConsoleConfig;
import touchline.app.Replay;
import touchline.record.EnvelopeWriter;
import touchline.record.Recording;
import touchline.record.ReplaySession;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.UdpConfig;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.UncheckedIOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The replay budgets of issue #13: replay at least 50x real time and seek within 200 ms on a
 * 30-minute six-robot recording, and Ctrl+C ending {@code touchline record} within 2 s.
 * Replay and seek go through the window's pipeline: the application core's {@code Replay}
 * playing into the console's bus with the model subscribed (robots, traffic meter, option
 * session, view stores), unpaced; the baseline in the same run is the same file played into a
 * consumer that does nothing (reading and decoding alone). A seek is timed until the replay's
 * stores and robots are reset and the first envelope at or after the target is delivered.
 * The recording is generated once (SyntheticTeam's demo rates) into {@code --dir} and kept
 * there. Ctrl+C: {@code touchline record} runs as a child JVM, gets live datagrams, then
 * SIGINT; timed from the signal until the process has exited, and the file must then be finished.
 */
@CommandLine.Command(name = "replay", mixinStandardHelpOptions = true,
        description = "Replay speed (x real time) and seek latency of a 30-minute six-robot recording through the "
                + "console's model, a two-file session, and Ctrl+C to a finished file of 'touchline record'.")
public final class ReplayBenchmark implements Callable<Integer> {

    private static final long START = 1_760_000_000_000_000L;
    private static final long ROBOT_CLOCK_AHEAD = 1_337_000;

    @CommandLine.Option(names = "--dir", defaultValue = "target/bench-replay",
            description = "where the generated recordings are kept (default: ${DEFAULT-VALUE})")
    Path dir;

    @CommandLine.Option(names = "--minutes", defaultValue = "30", description = "length of the recording (default: ${DEFAULT-VALUE})")
    int minutes;

    @CommandLine.Option(names = "--robots", defaultValue = "6", description = "robots in the team (default: ${DEFAULT-VALUE})")
    int robots;

    @CommandLine.Option(names = "--options", defaultValue = "8",
            description = "debug options each robot streams at 10 Hz, as a demo robot with every option switched on "
                    + "(the synthetic team's own plot is one; default: ${DEFAULT-VALUE})")
    int options;

    @CommandLine.Option(names = "--seeks", defaultValue = "200", description = "random seeks (default: ${DEFAULT-VALUE})")
    int seeks;

    @CommandLine.Option(names = "--stops", defaultValue = "5",
            description = "times 'touchline record' is started and stopped with SIGINT (0: skip; default: ${DEFAULT-VALUE})")
    int stops;

    @Override
    public Integer call() throws Exception {
        System.out.printf("machine: %d cores available to the JVM, %s %s%n", Runtime.getRuntime().availableProcessors(),
                System.getProperty("os.name"), System.getProperty("java.version"));
        Files.createDirectories(dir);
        String name = "replay-" + minutes + "min-" + robots + "robots-" + options + "options";
        Path laptop = dir.resolve(name + ".mcap");
        Path robotLog = dir.resolve(name + "-robot3.mcap");
        if (!Files.exists(laptop) || !Files.exists(robotLog)) {
            generate(laptop, robotLog);
        }
        System.out.printf("recording %s: %.1f MB; robot 3's own log %.1f MB%n", laptop, Files.size(laptop) / 1e6,
                Files.size(robotLog) / 1e6);
        double seconds = minutes * 60.0;

        Console console = new Console(ConsoleConfig.defaults().withUdp(
                UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0)));
        try {
            AtomicLong lastTime = new AtomicLong();
            console.field().replayStream().subscribe(e -> lastTime.set(e.timeMicros()));
            double baseline = Double.MAX_VALUE;
            long baselineCount = 0;
            double best = Double.MAX_VALUE;
            long delivered = 0;
            for (int round = 0; round < 3; round++) { // alternating, so both get the same warm-up
                UnpacedReplay run = UnpacedReplay.intoNothing(laptop);
                baseline = Math.min(baseline, run.seconds());
                baselineCount = run.envelopes();
                Replay r = console.replays().open(List.of(laptop), Map.of());
                long t0 = System.nanoTime();
                delivered = r.runFor(Long.MAX_VALUE);
                best = Math.min(best, (System.nanoTime() - t0) / 1e9);
            }
            System.out.printf("baseline, played into a consumer that does nothing: %d envelopes in %.2f s = %.0fx real "
                    + "time%n", baselineCount, baseline, seconds / baseline);
            System.out.printf("replay through the console's model: %d envelopes of %d min in %.2f s = %.0fx real time "
                            + "(budget >= 50x; %.2f x the baseline's time); %d robots in the model%n", delivered, minutes,
                    best, seconds / best, best / baseline, console.field().robots().robots().size());

            Replay r = console.replays().open(List.of(laptop), Map.of());
            long first = r.state().startMicros();
            long span = r.state().durationMicros();
            Random random = new Random(7);
            long[] times = new long[seeks];
            int backward = 0;
            long position = first;
            for (int i = 0; i < seeks; i++) {
                long target = first + (long) (random.nextDouble() * span);
                backward += target < position ? 1 : 0;
                long t0 = System.nanoTime();
                r.seek(target);
                r.runFor(1);
                times[i] = System.nanoTime() - t0;
                if (lastTime.get() < target) {
                    throw new IllegalStateException("seek to " + target + " delivered " + lastTime.get() + " first");
                }
                position = lastTime.get();
                r.runFor(2_000); // play on a little, as a user would, so the next seek has stores to empty
            }
            Arrays.sort(times);
            System.out.printf("seek (%d random, %d of them backward; until the replay's stores and robots are reset and the "
                            + "first envelope at the target is delivered): p50 %.1f ms, p99 %.1f ms, max %.1f ms "
                            + "(budget <= 200 ms)%n", seeks, backward, times[seeks / 2] / 1e6,
                    times[(int) Math.ceil(seeks * 0.99) - 1] / 1e6, times[seeks - 1] / 1e6);

            long t0 = System.nanoTime();
            Replay session = console.replays().open(List.of(laptop, robotLog), Map.of());
            double open = (System.nanoTime() - t0) / 1e9;
            for (ReplaySession.Part p : session.files()) {
                System.out.printf("  %s: %s%n", p.name(), p.offset().describe());
            }
            t0 = System.nanoTime();
            long merged = session.runFor(Long.MAX_VALUE);
            double play = (System.nanoTime() - t0) / 1e9;
            System.out.printf("two-file session (the laptop's and robot 3's own log, its clock %.3f s ahead): opened and "
                            + "aligned in %.2f s; %d envelopes played through the model in %.2f s = %.0fx real time%n",
                    ROBOT_CLOCK_AHEAD / 1e6, open, merged, play, seconds / play);
            console.replays().close();
        } finally {
            console.close();
        }

        if (stops > 0) {
            ctrlC();
        }
        return 0;
    }

    /** The team's recording, and robot 3's own log (its traffic and the GameController it heard) on a clock ahead. */
    private void generate(Path laptop, Path robotLog) throws IOException {
        System.out.printf("generating %d minutes of a %d-robot team (once; kept in %s) ...%n", minutes, robots, dir);
        Path a = dir.resolve(laptop.getFileName() + ".part");
        Path b = dir.resolve(robotLog.getFileName() + ".part");
        try (EnvelopeWriter w = new EnvelopeWriter(a, EnvelopeWriter.Options.defaults());
             EnvelopeWriter robot = new EnvelopeWriter(b, EnvelopeWriter.Options.defaults())) {
            java.util.PriorityQueue<Envelope> due = new java.util.PriorityQueue<>(
                    java.util.Comparator.comparingLong(Envelope::timeMicros));
            java.util.function.Consumer<Envelope> write = e -> {
                try {
                    w.write(e);
                    if (e.robotId() == 3 || e.channel() == Channel.GAMECONTROLLER) {
                        robot.write(new Envelope(e.timeMicros() + ROBOT_CLOCK_AHEAD, e.direction(), e.channel(),
                                e.peer(), e.robotId(), e.kind(), e.message(), e.raw(), e.error()));
                    }
                } catch (IOException x) {
                    throw new UncheckedIOException(x);
                }
            };
            new SyntheticTeam(robots, START, 3).generate(minutes * 60L, e -> {
                while (!due.isEmpty() && due.peek().timeMicros() <= e.timeMicros()) {
                    write.accept(due.poll());
                }
                write.accept(e);
                due.addAll(moreOptions(e));
            });
            due.forEach(write);
        }
        Files.move(a, laptop, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        Files.move(b, robotLog, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
    }

    private final touchline.protocol.FrameCodec frames = new touchline.protocol.FrameCodec(Integer.MAX_VALUE);

    /** For a robot's plot: the other options' plots of the same 10 Hz period, spread over it. */
    private List<Envelope> moreOptions(Envelope e) {
        touchline.proto.Fumanoid.DebugPlot plot = e.extension(touchline.proto.Fumanoid.debugPlot);
        if (plot == null || e.direction() != Direction.IN) {
            return List.of();
        }
        List<Envelope> more = new ArrayList<>();
        touchline.protocol.Framing framing = e.robotId() == 1 ? touchline.protocol.Framing.LEGACY
                : touchline.protocol.Framing.LENGTH_PREFIX;
        for (int i = 1; i < options; i++) {
            touchline.proto.Fumanoid.Message m = ((touchline.proto.Fumanoid.Message) e.message()).toBuilder()
                    .setExtension(touchline.proto.Fumanoid.debugPlot, plot.toBuilder().setOption("option" + i).build())
                    .build();
            more.add(new Envelope(e.timeMicros() + i * 100_000L / options, e.direction(), e.channel(), e.peer(),
                    e.robotId(), e.kind(), m, frames.encode(framing, m.toByteArray()), null));
        }
        return more;
    }

    private static final Pattern LISTENING = Pattern.compile("recording UDP port (\\d+) to ");

    /** Starts {@code touchline record} as a child JVM {@link #stops} times, feeds it, sends SIGINT, times the exit. */
    private void ctrlC() throws Exception {
        List<Envelope> traffic = new ArrayList<>();
        new SyntheticTeam(robots, START, 5).generate(2, e -> {
            if (e.direction() == Direction.IN && e.channel() == Channel.FUMANOID) {
                traffic.add(e);
            }
        });
        long[] took = new long[stops];
        String signal = "INT";
        for (int i = 0; i < stops; i++) {
            Path file = dir.resolve("ctrl-c-" + i + ".mcap");
            Files.deleteIfExists(file);
            Process p = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                    "-XX:+UseZGC", "-cp", System.getProperty("java.class.path"), "touchline.cli.Main", "record",
                    "--out", file.toString(), "--port", "0", "--bind", "127.0.0.1")
                    .redirectErrorStream(true).start();
            BufferedReader out = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8));
            int port = 0;
            while (port == 0) {
                String line = out.readLine();
                if (line == null) {
                    break;
                }
                Matcher m = LISTENING.matcher(line);
                if (m.find()) {
                    port = Integer.parseInt(m.group(1));
                }
            }
            if (port == 0) {
                throw new IllegalStateException("touchline record did not start: exit " + p.waitFor());
            }
            try (DatagramSocket robot = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
                long t0 = System.nanoTime();
                for (Envelope e : traffic) { // two seconds of the team, at its pace
                    long due = t0 + (e.timeMicros() - traffic.get(0).timeMicros()) * 1000;
                    LockSupport.parkNanos(due - System.nanoTime());
                    robot.send(new DatagramPacket(e.raw(), e.raw().length, InetAddress.getLoopbackAddress(), port));
                }
            }
            Thread drain = new Thread(() -> drain(p.getInputStream()), "bench-record-output");
            drain.setDaemon(true);
            drain.start();
            long t0 = System.nanoTime();
            kill(signal, p.pid());
            if (!p.waitFor(10, TimeUnit.SECONDS)) {
                // a child of a shell that ignores SIGINT inherits that; SIGTERM takes the same way out
                System.out.println("  SIGINT was ignored (inherited from the shell); measuring with SIGTERM instead");
                signal = "TERM";
                t0 = System.nanoTime();
                kill(signal, p.pid());
                p.waitFor(30, TimeUnit.SECONDS);
            }
            took[i] = System.nanoTime() - t0;
            try (Recording r = Recording.open(file)) {
                if (!r.problems().isEmpty() || r.mcap().messageCount() == 0 || !r.mcap().indexed()) {
                    throw new IllegalStateException("the file is not finished after SIG" + signal + ": " + r.problems());
                }
            }
        }
        long[] sorted = took.clone();
        Arrays.sort(sorted);
        System.out.printf("Ctrl+C (SIG%s) to a finished file, %d runs of 'touchline record' fed 2 s of the team: p50 %.0f ms,"
                        + " max %.0f ms (budget <= 2 s)%n", signal, stops, sorted[stops / 2] / 1e6,
                sorted[stops - 1] / 1e6);
    }

    private static void kill(String signal, long pid) throws IOException, InterruptedException {
        new ProcessBuilder("kill", "-" + signal, Long.toString(pid)).inheritIO().start().waitFor();
    }

    private static void drain(InputStream in) {
        try {
            in.transferTo(java.io.OutputStream.nullOutputStream());
        } catch (IOException ignored) {
            // the child has exited
        }
    }
}
