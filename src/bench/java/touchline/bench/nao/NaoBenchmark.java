package touchline.bench.nao;

import org.zeromq.SocketType;
import org.zeromq.ZContext;
import org.zeromq.ZMQ;
import touchline.proto.Nao.HAWActorRPCRequest;
import touchline.transport.nao.CallOutcome;
import touchline.transport.nao.CameraSettings;
import touchline.transport.nao.ConnectionState;
import touchline.transport.nao.NaoClientKeys;
import touchline.security.KeyDir;
import touchline.transport.nao.NaoCall;
import touchline.transport.nao.NaoCameraStream;
import touchline.transport.nao.NaoLink;
import touchline.transport.nao.NaoLinkConfig;
import touchline.protocol.nao.CameraFormat;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Console-side NAO link benchmark: starts {@code touchline-nao-sim} on loopback and measures
 * (1) the round trip of {@code ALMotion.ping} through {@link NaoLink} against baselines
 * measured call by call in the same run, each a raw JeroMQ DEALER sending the same bytes: to
 * the raw libzmq ROUTER echo the simulator serves with {@code --echo-port} (the budget's
 * baseline: same process, same path as the RPC), to in-process JeroMQ echoes (on their own
 * context, and on the client's context, where one I/O thread serves both ends), and to the
 * simulator itself; (2) short-call latency while long {@code say} calls occupy
 * half the workers; (3) camera frames per second and bytes per frame delivered to a viewer
 * at 640x480 and 1280x960; (4) the cost of CURVE: {@code ALMotion.ping} through NaoLink with
 * CURVE keys to a second simulator started with {@code --curve-secret}, against the same call
 * without CURVE to the first, alternating call by call (budget: p50 ratio ≤ 1.2). Prints a
 * Markdown table for docs/benchmarks.md.
 *
 * <p>Usage: {@code NaoBenchmark [--bin robot-side/build/bin] [--seconds 4] [--curve-only]}
 */
public final class NaoBenchmark {

    private static final Pattern RPC = Pattern.compile("rpc listening on port (\\d+)");
    private static final Pattern CAM = Pattern.compile("camera listening on port (\\d+)");
    private static final Pattern ECHO = Pattern.compile("echo listening on port (\\d+)");

    private final Path binary;
    private final int seconds;
    private final boolean curveOnly;

    public NaoBenchmark(Path binary, int seconds) {
        this(binary, seconds, false);
    }

    /** @param curveOnly measure only the cost of CURVE (part 4) */
    public NaoBenchmark(Path binary, int seconds, boolean curveOnly) {
        this.binary = binary;
        this.seconds = seconds;
        this.curveOnly = curveOnly;
    }

    /** Runs from the command line's arguments; returns the exit status (1: the simulator is not built). */
    public static int run(String[] args) throws Exception {
        touchline.cli.RobotSideBinaries binaries = new touchline.cli.RobotSideBinaries();
        int seconds = 4;
        for (int i = 0; i < args.length - 1; i++) {
            if (args[i].equals("--bin")) {
                binaries = new touchline.cli.RobotSideBinaries(Path.of(args[i + 1]));
            } else if (args[i].equals("--seconds")) {
                seconds = Integer.parseInt(args[i + 1]);
            }
        }
        if (binaries.missing("touchline-nao-sim").isPresent()) {
            System.err.println(binaries.missing("touchline-nao-sim").get());
            return 1;
        }
        Path binary = binaries.of("touchline-nao-sim");
        new NaoBenchmark(binary, seconds, Arrays.asList(args).contains("--curve-only")).run();
        return 0;
    }

    void run() throws Exception {
        Process sim = new ProcessBuilder(binary.toString(), "--bind", "127.0.0.1", "--rpc-port", "0", "--cam-port", "0",
                "--workers", "4", "--echo-port", "0").redirectError(ProcessBuilder.Redirect.DISCARD).start();
        try {
            int[] ports = ports(sim);
            System.out.println("| what | figure (console side, Java) | budget |");
            System.out.println("| --- | --- | --- |");
            if (!curveOnly) {
                roundTrip(ports[0], ports[2]);
                shortCallsUnderLoad(ports[0]);
                camera(ports[1], 2);
                camera(ports[1], 3);
            }
            curve(ports[0]);
        } finally {
            sim.destroy();
            sim.waitFor(5, TimeUnit.SECONDS);
        }
    }

    private static int[] ports(Process sim) throws Exception {
        BufferedReader r = new BufferedReader(new InputStreamReader(sim.getInputStream(), StandardCharsets.UTF_8));
        int rpc = -1;
        int cam = -1;
        int echo = -1;
        String line;
        while ((rpc < 0 || cam < 0 || echo < 0) && (line = r.readLine()) != null) {
            Matcher m = RPC.matcher(line);
            if (m.find()) {
                rpc = Integer.parseInt(m.group(1));
            }
            m = CAM.matcher(line);
            if (m.find()) {
                cam = Integer.parseInt(m.group(1));
            }
            m = ECHO.matcher(line);
            if (m.find()) {
                echo = Integer.parseInt(m.group(1));
            }
        }
        if (rpc < 0 || cam < 0 || echo < 0) {
            throw new IllegalStateException("touchline-nao-sim did not report its ports");
        }
        return new int[] {rpc, cam, echo};
    }

    /**
     * NaoLink ping with CURVE (a second simulator with keys) against NaoLink ping without, one
     * call in flight, alternating call by call so machine noise hits both alike.
     */
    private void curve(int insecurePort) throws Exception {
        Path keys = Files.createTempDirectory("touchline-bench-keys");
        new KeyDir(keys).create(true, new java.security.SecureRandom(), java.time.Instant.now());
        Process secure = new ProcessBuilder(binary.toString(), "--bind", "127.0.0.1", "--rpc-port", "0", "--cam-port",
                "0", "--workers", "4", "--echo-port", "0", "--curve-secret", keys.resolve("nao-server.secret").toString(),
                "--curve-clients", keys.resolve("console.public").toString())
                .redirectError(ProcessBuilder.Redirect.DISCARD).start();
        try (NaoLink plain = link(insecurePort, null);
             NaoLink curve = link(ports(secure)[0], NaoClientKeys.load(new KeyDir(keys)))) {
            NaoCall ping = NaoCall.of("ALMotion", "ping");
            // warm-up: long enough for the JIT to compile JeroMQ's pure-Java CURVE crypto too
            for (int i = 0; i < 5_000; i++) {
                plain.call(ping).get();
                curve.call(ping).get();
            }
            List<Long> plainNs = new ArrayList<>();
            List<Long> curveNs = new ArrayList<>();
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
            while (System.nanoTime() < end) {
                for (NaoLink l : List.of(plain, curve)) {
                    long t0 = System.nanoTime();
                    CallOutcome outcome = l.call(ping).get();
                    (l == plain ? plainNs : curveNs).add(System.nanoTime() - t0);
                    if (!outcome.ok()) {
                        throw new IllegalStateException("ping failed: " + outcome.describe());
                    }
                }
            }
            double[] p = percentiles(plainNs);
            double[] c = percentiles(curveNs);
            row("NaoLink `ALMotion.ping` without CURVE (baseline), p50 / p99", p, plainNs.size());
            row("NaoLink `ALMotion.ping` with CURVE (JeroMQ client ↔ libzmq server + ZAP), p50 / p99", c, curveNs.size());
            System.out.printf("| **ratio p50 with CURVE / without** | **%.2f** | ≤ 1.2 |%n", c[0] / p[0]);
            System.out.printf("| ratio p99 with CURVE / without | %.2f | — |%n", c[1] / p[1]);
        } finally {
            secure.destroy();
            secure.waitFor(5, TimeUnit.SECONDS);
            for (String f : KeyDir.FILES) {
                Files.deleteIfExists(keys.resolve(f));
            }
            Files.deleteIfExists(keys);
        }
    }

    private NaoLink link(int port) throws InterruptedException {
        return link(port, null);
    }

    private NaoLink link(int port, NaoClientKeys keys) throws InterruptedException {
        NaoLink link = new NaoLink("127.0.0.1", port, NaoLinkConfig.defaults(), e -> { }, keys, new touchline.app.SystemClock(), new touchline.app.SystemClock()).start();
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
        while (link.state() != ConnectionState.ONLINE && System.nanoTime() < end) {
            Thread.sleep(5);
        }
        if (link.state() != ConnectionState.ONLINE) {
            throw new IllegalStateException("NaoLink did not come online");
        }
        return link;
    }

    private void roundTrip(int rpcPort, int simEchoPort) throws Exception {
        byte[] payload = HAWActorRPCRequest.newBuilder().setModule("ALMotion").setMethod("ping")
                .setDeadlineMillis(System.currentTimeMillis() + 60_000).build().toByteArray();
        try (ZContext zmq = new ZContext(1); ZContext echoZmq = new ZContext(1); NaoLink link = link(rpcPort)) {
            // In-process JeroMQ echoes: one on the clients' context (one I/O thread serves both
            // ends of the TCP connection, which no remote robot can do), one on its own context.
            Thread sharedEcho = echo(zmq, "bench-echo-shared");
            Thread ownEcho = echo(echoZmq, "bench-echo-own");
            ZMQ.Socket toSimEcho = dealer(zmq, "tcp://127.0.0.1:" + simEchoPort);
            ZMQ.Socket toSharedEcho = dealer(zmq, sharedEcho.getName().substring(sharedEcho.getName().indexOf('@') + 1));
            ZMQ.Socket toOwnEcho = dealer(zmq, ownEcho.getName().substring(ownEcho.getName().indexOf('@') + 1));
            ZMQ.Socket toSim = dealer(zmq, "tcp://127.0.0.1:" + rpcPort);
            NaoCall ping = NaoCall.of("ALMotion", "ping");
            List<ZMQ.Socket> raw = List.of(toSimEcho, toSharedEcho, toOwnEcho, toSim);
            // warm-up (JIT, connections)
            for (int i = 0; i < 2000; i++) {
                for (ZMQ.Socket s : raw) {
                    rawRoundTrip(s, payload, i);
                }
                link.call(ping).get();
            }
            List<List<Long>> rawNs = new ArrayList<>();
            raw.forEach(s -> rawNs.add(new ArrayList<>()));
            List<Long> linkNs = new ArrayList<>();
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
            long id = 1_000_000;
            // One call in flight, the variants alternating call by call so noise hits all alike.
            while (System.nanoTime() < end) {
                for (int v = 0; v < raw.size(); v++) {
                    rawNs.get(v).add(rawRoundTrip(raw.get(v), payload, id++));
                }
                long t0 = System.nanoTime();
                CallOutcome outcome = link.call(ping).get();
                linkNs.add(System.nanoTime() - t0);
                if (!outcome.ok()) {
                    throw new IllegalStateException("ping failed: " + outcome.describe());
                }
            }
            double[] simEcho = percentiles(rawNs.get(0));
            double[] shared = percentiles(rawNs.get(1));
            double[] own = percentiles(rawNs.get(2));
            double[] r = percentiles(rawNs.get(3));
            double[] l = percentiles(linkNs);
            row("raw JeroMQ DEALER ↔ libzmq ROUTER echo in touchline-nao-sim, same bytes (baseline), p50 / p99", simEcho, linkNs.size());
            row("raw JeroMQ DEALER ↔ in-process JeroMQ ROUTER echo on its own context, p50 / p99", own, linkNs.size());
            row("raw JeroMQ DEALER ↔ in-process JeroMQ ROUTER echo on the client's context (shared I/O thread), p50 / p99", shared, linkNs.size());
            row("raw JeroMQ DEALER ↔ touchline-nao-sim `ALMotion.ping`, p50 / p99", r, linkNs.size());
            row("NaoLink `ALMotion.ping` (future completed), p50 / p99", l, linkNs.size());
            System.out.printf("| **ratio p50 NaoLink / echo in touchline-nao-sim** | **%.2f** | ≤ 1.5 |%n", l[0] / simEcho[0]);
            System.out.printf("| ratio p50 NaoLink / in-process echo, own context | %.2f | — |%n", l[0] / own[0]);
            System.out.printf("| ratio p50 NaoLink / in-process echo, shared I/O thread | %.2f | — |%n", l[0] / shared[0]);
            System.out.printf("| ratio p50 NaoLink / raw DEALER to the simulator (NaoLink's own cost) | %.2f | — |%n", l[0] / r[0]);
            sharedEcho.interrupt();
            ownEcho.interrupt();
        }
    }

    /** Starts a JeroMQ ROUTER echo on {@code zmq}; the thread's name ends in {@code @endpoint}. */
    private static Thread echo(ZContext zmq, String name) {
        ZMQ.Socket echo = zmq.createSocket(SocketType.ROUTER);
        echo.bind("tcp://127.0.0.1:*");
        Thread thread = new Thread(() -> {
            try {
                while (!Thread.currentThread().isInterrupted()) {
                    byte[] id = echo.recv(0);
                    if (id == null) {
                        return;
                    }
                    List<byte[]> frames = new ArrayList<>();
                    while (echo.hasReceiveMore()) {
                        frames.add(echo.recv(0));
                    }
                    echo.send(id, ZMQ.SNDMORE);
                    for (int i = 0; i < frames.size(); i++) {
                        echo.send(frames.get(i), i < frames.size() - 1 ? ZMQ.SNDMORE : 0);
                    }
                }
            } catch (RuntimeException closed) {
                // context closed at the end of the run
            }
        }, name + "@" + echo.getLastEndpoint());
        thread.setDaemon(true);
        thread.start();
        return thread;
    }

    private static ZMQ.Socket dealer(ZContext zmq, String endpoint) {
        ZMQ.Socket s = zmq.createSocket(SocketType.DEALER);
        s.setImmediate(false);
        s.setLinger(0);
        s.connect(endpoint);
        return s;
    }

    private static long rawRoundTrip(ZMQ.Socket dealer, byte[] payload, long id) {
        byte[] idBytes = ByteBuffer.allocate(8).putLong(id).array();
        long t0 = System.nanoTime();
        dealer.send(idBytes, ZMQ.SNDMORE);
        dealer.send(new byte[0], ZMQ.SNDMORE);
        dealer.send(payload, 0);
        dealer.recv(0);
        while (dealer.hasReceiveMore()) {
            dealer.recv(0);
        }
        return System.nanoTime() - t0;
    }

    private void shortCallsUnderLoad(int rpcPort) throws Exception {
        try (NaoLink link = link(rpcPort)) {
            String text = "This sentence keeps a worker busy for a long time. ".repeat(20);
            NaoCall say = NaoCall.of("ALTextToSpeech", "say", text);
            NaoCall ping = NaoCall.of("ALMotion", "ping");
            List<CompletableFuture<CallOutcome>> longCalls = new ArrayList<>();
            longCalls.add(link.call(say, 120_000));
            longCalls.add(link.call(NaoCall.of("ALMotion", "angleInterpolation", "HeadYaw", 1.0f,
                    (float) (seconds + 30), true), 120_000));
            Thread.sleep(200); // let the long calls reach their workers
            List<Long> ns = new ArrayList<>();
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
            int failures = 0;
            while (System.nanoTime() < end) {
                long t0 = System.nanoTime();
                if (!link.call(ping).get().ok()) {
                    failures++;
                }
                ns.add(System.nanoTime() - t0);
            }
            long stillRunning = longCalls.stream().filter(f -> !f.isDone()).count();
            double[] p = percentiles(ns);
            System.out.printf("| short calls while %d of 4 workers run long calls (say, angleInterpolation): p50 / p99 / max | %.3f ms / %.2f ms / %.1f ms (%d calls, %d failed) | p99 ≤ 50 ms |%n",
                    stillRunning, p[0] / 1e6, p[1] / 1e6, p[2] / 1e6, ns.size(), failures);
            link.call(NaoCall.of("ALTextToSpeech", "stopAll")).get();
            link.call(NaoCall.of("ALMotion", "killMove")).get();
        }
    }

    private void camera(int camPort, int resolution) throws Exception {
        try (NaoCameraStream stream = new NaoCameraStream("127.0.0.1", camPort, e -> { }, null, new touchline.app.SystemClock(), new touchline.app.SystemClock()).start()) {
            stream.configure(new CameraSettings(resolution, 11, 30));
            try (AutoCloseable viewer = stream.subscribe()) {
                long warm = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
                while (stream.framesReceived() < 5 && System.nanoTime() < warm) {
                    Thread.sleep(10);
                }
                long startFrames = stream.framesReceived();
                long t0 = System.nanoTime();
                Thread.sleep(TimeUnit.SECONDS.toMillis(seconds));
                long frames = stream.framesReceived() - startFrames;
                double elapsed = (System.nanoTime() - t0) / 1e9;
                double bytes = stream.bytesPerFrame();
                long raw = CameraFormat.rawRgbBytes(resolution);
                String size = CameraFormat.width(resolution) + "×" + CameraFormat.height(resolution);
                System.out.printf("| camera %s at 30 fps configured, frames/s to one NaoCameraStream viewer | %.1f | %s |%n",
                        size, frames / elapsed, resolution == 2 ? "≥ 30 fps" : "≥ 15 fps");
                System.out.printf("| bytes per frame %s | %.0f B = 1/%.0f of raw RGB (%d B) | ≤ 1/15 |%n",
                        size, bytes, raw / Math.max(1, bytes), raw);
            }
        }
    }

    private static void row(String what, double[] p, int n) {
        System.out.printf("| %s | %.3f ms / %.3f ms (%d calls) | — |%n", what, p[0] / 1e6, p[1] / 1e6, n);
    }

    /** p50, p99, max in nanoseconds. */
    private static double[] percentiles(List<Long> values) {
        long[] a = values.stream().mapToLong(Long::longValue).toArray();
        Arrays.sort(a);
        return new double[] {a[a.length / 2], a[Math.min(a.length - 1, (int) (a.length * 0.99))], a[a.length - 1]};
    }
}
