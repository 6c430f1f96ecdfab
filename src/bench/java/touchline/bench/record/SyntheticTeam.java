package touchline.bench.record;

import touchline.proto.Fumanoid;
import touchline.protocol.FrameCodec;
import touchline.protocol.Framing;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.UnknownHostException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Random;
import java.util.function.Consumer;

/**
 * Deterministic synthetic traffic of a simulated team, as the live transports would publish
 * it: Status keep-alives every 200 ms per robot, debug text, plots (10 Hz) and tables,
 * GameController packets (HL v12, 2 Hz) going INITIAL → READY → SET → PLAYING with a goal,
 * console requests, a NAO call, link events, occasional malformed datagrams, and one robot
 * dropping out for a few seconds. Used by the tests, the sample recording and the benchmark.
 */
public final class SyntheticTeam {

    private final int robots;
    private final long startMicros;
    private final Random random;
    private final FrameCodec frames = new FrameCodec(Integer.MAX_VALUE);

    public SyntheticTeam(int robots, long startMicros, long seed) {
        this.robots = robots;
        this.startMicros = startMicros;
        this.random = new Random(seed);
    }

    /** Generates {@code seconds} of traffic in time order into {@code out}. */
    public void generate(long seconds, Consumer<Envelope> out) {
        // produced one second at a time and sorted, so the stream is in time order like a live one
        List<Envelope> second = new ArrayList<>();
        for (long s = 0; s < seconds; s++) {
            second.clear();
            long t0 = startMicros + s * 1_000_000L;
            for (int id = 1; id <= robots; id++) {
                if (id == 2 && s >= seconds / 2 && s < seconds / 2 + 4) {
                    continue; // robot 2 loses Wi-Fi for four seconds
                }
                robotSecond(id, s, t0 + id * 1_731L, second);
            }
            for (int k = 0; k < 2; k++) {
                second.add(gc(t0 + k * 500_000L + 17, s, seconds));
            }
            if (s == 1) {
                second.add(new Envelope(t0 + 3, Direction.OUT, Channel.NAO_RPC, peer(99, 5555), Envelope.NO_ROBOT,
                        "rpc", null, "say hello".getBytes(StandardCharsets.UTF_8), null));
                second.add(new Envelope(t0 + 4, Direction.IN, Channel.LINK_EVENT, null, Envelope.NO_ROBOT,
                        "nao-online", null, "NAO online".getBytes(StandardCharsets.UTF_8), null));
            }
            second.sort(Comparator.comparingLong(Envelope::timeMicros));
            second.forEach(out);
        }
    }

    private void robotSecond(int id, long s, long t0, List<Envelope> out) {
        InetSocketAddress peer = peer(10 + id, 3838 + id * 10);
        Framing framing = id == 1 ? Framing.LEGACY : Framing.LENGTH_PREFIX;
        for (int k = 0; k < 5; k++) {
            long t = t0 + k * 200_000L;
            Fumanoid.Status status = Fumanoid.Status.newBuilder()
                    .setTimestamp((t - startMicros) / 1000 + 5_000L * id)
                    .setTeamID(13).setTimeOnline((int) s)
                    .setRobotPosition(Fumanoid.Position.newBuilder()
                            .setX((float) (1000 * Math.sin(t / 3e6 + id))).setY((float) (600 * Math.cos(t / 4e6)))
                            .setTheta((float) (t / 1e6 % 6.28)))
                    .setActiveRole(id == 1 ? "goalie" : "striker").setCurrentState("walking")
                    .setRobotName("robot" + id).setBatteryPercent((int) Math.max(5, 100 - s / 10))
                    .setGameState(s < 10 ? "INITIAL" : s < 20 ? "READY" : "PLAYING").build();
            out.add(fumanoid(t, peer, id, "status", framing,
                    Fumanoid.Message.newBuilder().setRobotID(id).setExtension(Fumanoid.status, status).build()));
        }
        for (int k = 0; k < 10; k++) {
            long t = t0 + 50_000L + k * 100_000L;
            Fumanoid.DebugPlot plot = Fumanoid.DebugPlot.newBuilder().setOption("motion.speed")
                    .setTimestamp((t - startMicros) / 1000)
                    .addSamples(Fumanoid.PlotSample.newBuilder().setSeries("vx").setValue(Math.sin(t / 5e5)))
                    .addSamples(Fumanoid.PlotSample.newBuilder().setSeries("vy").setValue(random.nextGaussian()))
                    .build();
            out.add(fumanoid(t, peer, id, "debugPlot", framing,
                    Fumanoid.Message.newBuilder().setRobotID(id).setExtension(Fumanoid.debugPlot, plot).build()));
        }
        out.add(fumanoid(t0 + 70_000L, peer, id, "debugText", framing, Fumanoid.Message.newBuilder().setRobotID(id)
                .setExtension(Fumanoid.debugText, Fumanoid.DebugText.newBuilder().setOption("behaviour")
                        .setText("second " + s + ": " + (random.nextBoolean() ? "search ball" : "approach ball"))
                        .setTimestamp((t0 - startMicros) / 1000).build()).build()));
        if (s % 2 == 0) {
            out.add(fumanoid(t0 + 90_000L, peer, id, "debugTable", framing, Fumanoid.Message.newBuilder().setRobotID(id)
                    .setExtension(Fumanoid.debugTable, Fumanoid.DebugTable.newBuilder().setOption("servos")
                            .addHeader("servo").addHeader("temp")
                            .addRows(Fumanoid.TableRow.newBuilder().addCells("hip").addCells(Integer.toString(40 + random.nextInt(10))))
                            .addRows(Fumanoid.TableRow.newBuilder().addCells("knee").addCells(Integer.toString(45 + random.nextInt(10))))
                            .build()).build()));
        }
        if (s % 10 == 3) {
            Fumanoid.Message req = Fumanoid.Message.newBuilder().setRobotID(0)
                    .setExtension(Fumanoid.debugOptionRequest, Fumanoid.DebugOptionRequest.newBuilder()
                            .setName("motion.speed").setEnable(true).build()).build();
            out.add(fumanoid(t0 + 110_000L, Direction.OUT, peer, id, "debugOptionRequest", framing, req));
        }
        if (s % 15 == 7) {
            byte[] junk = new byte[7 + random.nextInt(20)];
            random.nextBytes(junk);
            junk[0] = 0;
            junk[1] = 0;
            junk[2] = 0;
            junk[3] = 99;
            out.add(new Envelope(t0 + 130_000L, Direction.IN, Channel.FUMANOID, peer, id, "malformed", null, junk,
                    "length header says 99 payload bytes, datagram has " + (junk.length - 4)));
        }
    }

    private Envelope fumanoid(long t, InetSocketAddress peer, int id, String kind, Framing framing, Fumanoid.Message m) {
        return fumanoid(t, Direction.IN, peer, id, kind, framing, m);
    }

    private Envelope fumanoid(long t, Direction dir, InetSocketAddress peer, int id, String kind, Framing framing,
                              Fumanoid.Message m) {
        return new Envelope(t, dir, Channel.FUMANOID, peer, id, kind, m, frames.encode(framing, m.toByteArray()), null);
    }

    /** An HL v12 GameController packet: INITIAL, READY at 10 s, SET at 15 s, PLAYING at 20 s, a goal at 2/3. */
    private Envelope gc(long t, long s, long seconds) {
        byte[] p = new byte[688];
        p[0] = 'R';
        p[1] = 'G';
        p[2] = 'm';
        p[3] = 'e';
        p[4] = 12;
        p[6] = (byte) (s * 2);
        p[7] = 5;
        p[9] = (byte) (s < 10 ? 0 : s < 15 ? 1 : s < 20 ? 2 : s < seconds - 5 ? 3 : 4);
        p[24] = 13;
        p[356] = 7;
        p[24 + 2] = (byte) (s >= seconds * 2 / 3 ? 1 : 0);
        return new Envelope(t, Direction.IN, Channel.GAMECONTROLLER, peer(1, 3838), Envelope.NO_ROBOT, "hl12", null, p,
                null);
    }

    private static InetSocketAddress peer(int host, int port) {
        try {
            return new InetSocketAddress(InetAddress.getByAddress(new byte[]{10, 0, 13, (byte) host}), port);
        } catch (UnknownHostException e) {
            throw new IllegalStateException(e);
        }
    }
}
