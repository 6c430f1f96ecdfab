package touchline.app;

import touchline.app.game.EmbeddedGameController;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.game.hsl.Competition;
import touchline.game.hsl.HslActionSyntax;
import touchline.game.hsl.HslGame;
import touchline.game.hsl.HslRules;
import touchline.protocol.gamecontroller.TeamColour;
import touchline.model.MatchDebugRule;
import touchline.model.OptionState;
import touchline.proto.Fumanoid;
import touchline.testing.Await;
import touchline.testing.RobotProcess;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.UdpConfig;
import touchline.transport.gamecontroller.GcConfig;
import touchline.transport.gamecontroller.GcProfile;

import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A game with the embedded HSL GameController against the real firmware binaries (issue 40):
 * the console chooses each robot's match items outside play and the robots confirm them; in
 * play each robot sends at most one datagram a period, within the size budget, with exactly the
 * chosen items, and the console's plots and field move once per digest; a robot sending two a
 * period and one sending an over-size digest are flagged, a robot with no choice sends its
 * Status alone; when the game is over streaming resumes.
 */
@Tag("integration")
class MatchDigestGameIntegrationTest {

    private static final InetSocketAddress ANY_LOOPBACK_PORT = new InetSocketAddress(InetAddress.getLoopbackAddress(), 0);
    private static final long PERIOD_MICROS = 1_000_000;

    private static int freeLoopbackPort() throws Exception {
        try (DatagramSocket probe = new DatagramSocket(ANY_LOOPBACK_PORT)) {
            return probe.getLocalPort();
        }
    }

    /** Through the referee's one owner thread, as every face does; returns once applied. */
    private static void perform(EmbeddedGameController gc, String command) {
        assertTrue(gc.runtime().perform(new HslActionSyntax().parse(command).action()).join().applied(), command);
    }

    /** The robot's whole datagrams (not a digest's parts) since {@code fromMicros}. */
    private static List<Envelope> datagrams(List<Envelope> heard, int robot, long fromMicros) {
        return heard.stream().filter(e -> e.robotId() == robot && e.timeMicros() >= fromMicros).toList();
    }

    private static long digests(List<Envelope> heard, int robot) {
        return heard.stream().filter(e -> e.robotId() == robot && e.kind().equals("matchDigest")).count();
    }

    @Test
    void inPlayEachRobotSendsOneDigestPerPeriodWithItsChosenItems() throws Exception {
        touchline.testing.Requirement.robotSide("touchline-robot");
        List<Envelope> heard = new CopyOnWriteArrayList<>();
        int gcPort = freeLoopbackPort();
        ConsoleConfig config = ConsoleConfig.defaults()
                .withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0))
                .withGameControllerPort(gcPort);
        HslGame game = new HslGame(HslRules.forVersion(20, Competition.MIDDLE_ADVANCED), 13,
                new TeamColour[]{TeamColour.BLUE, TeamColour.YELLOW}, 14,
                new TeamColour[]{TeamColour.RED, TeamColour.BLACK}, new SystemClock());
        try (Console console = new Console(config).start();
             RobotProcess chosen = RobotProcess.robot(2, console.field().port(), "--gc-return-rate", "0").start();
             RobotProcess twice = RobotProcess.robot(3, console.field().port(), "--gc-return-rate", "0", "--match-sends", "2").start();
             RobotProcess big = RobotProcess.robot(4, console.field().port(), "--gc-return-rate", "0").start();
             RobotProcess plain = RobotProcess.robot(5, console.field().port(), "--gc-return-rate", "0").start()) {
            // the test's profile: one a second, 700 bytes, one fragment
            console.field().matchRule().use(new MatchDebugRule.Limits(PERIOD_MICROS, 700, 1));
            for (int id = 2; id <= 5; id++) {
                int robot = id;
                Await.until("option list of robot " + robot, () -> console.field().options().options(robot).listReceived());
            }
            console.field().options().setWanted(2, "demo.text", true);
            console.field().options().setMatchItems(2, List.of("demo.plotter", "demo.field"));
            console.field().options().setMatchItems(3, List.of("demo.plotter"));
            console.field().options().setMatchItems(4, List.of("demo.image", "demo.plotter", "havimo.region", "havimo.grid",
                    "demo.table", "demo.field"));
            Await.until("robot 2 confirms its match items", () -> rankOnRobot(console, 2, "demo.plotter") == 1
                    && rankOnRobot(console, 2, "demo.field") == 2);
            Await.until("robots 3 and 4 confirm theirs", () -> rankOnRobot(console, 3, "demo.plotter") == 1
                    && rankOnRobot(console, 4, "demo.field") == 6);
            assertTrue(console.field().options().options(2).option("demo.plotter").orElseThrow().matchConfirmed());
            Await.until("demo.text streams before the game", () -> streaming(console, 2, "demo.text"));

            console.field().bus().subscribe(e -> {
                if (e.direction() == Direction.IN && e.channel() == Channel.FUMANOID && e.robotId() >= 2) {
                    heard.add(e);
                }
            });
            List<InetSocketAddress> robots = new ArrayList<>();
            for (RobotProcess r : List.of(chosen, twice, big, plain)) {
                robots.add(new InetSocketAddress(InetAddress.getLoopbackAddress(), r.port()));
            }
            robots.add(new InetSocketAddress(InetAddress.getLoopbackAddress(), gcPort));
            EmbeddedGameController gc = console.referee().start(game, new GcConfig(GcProfile.HSL20, false, robots,
                    ANY_LOOPBACK_PORT, ANY_LOOPBACK_PORT, null, 500, false));
            perform(gc, "kickoff 13");
            perform(gc, "set");
            perform(gc, "play");

            Await.until("robot 2 sends digests", () -> digests(heard, 2) >= 1);
            long inPlay = heard.stream().filter(e -> e.robotId() == 2 && e.kind().equals("matchDigest"))
                    .findFirst().orElseThrow().timeMicros();
            long plotPointsBefore = plotPoints(console, 2);
            long digestsBefore = digests(heard, 2);
            Await.until("five digests of robot 2", () -> digests(heard, 2) >= digestsBefore + 5);
            long plotPointsAfter = plotPoints(console, 2);
            long digestsAfter = digests(heard, 2);

            // robot 2: one datagram a period, the digest, within the budget, with its two items
            List<Envelope> two = datagrams(heard, 2, inPlay);
            for (int i = 0; i < two.size(); i++) {
                Envelope e = two.get(i);
                assertEquals("matchDigest", e.kind(), "in play robot 2 sends nothing but its digest");
                assertTrue(e.size() <= 1400, e.size() + " bytes");
                Fumanoid.MatchDigest d = e.extension(Fumanoid.matchDigest);
                assertEquals(List.of("demo.plotter", "demo.field"), d.getItemsList().stream()
                        .map(m -> m.hasExtension(Fumanoid.debugPlot) ? m.getExtension(Fumanoid.debugPlot).getOption()
                                : m.getExtension(Fumanoid.fieldObjects).getOption()).toList());
                assertEquals(0, d.getOmitted());
                assertTrue(List.of("READY", "SET", "PLAYING").contains(d.getStatus().getGameState()));
                if (i > 0) {
                    long gap = e.timeMicros() - two.get(i - 1).timeMicros();
                    assertTrue(gap >= PERIOD_MICROS / 2, "two datagrams " + gap + " µs apart");
                }
            }
            long span = two.get(two.size() - 1).timeMicros() - two.get(0).timeMicros();
            assertTrue(two.size() <= span / PERIOD_MICROS + 2, two.size() + " datagrams in " + span + " µs");
            // the plot moves once per digest (one point a series), the field shows the newest
            assertTrue(plotPointsAfter - plotPointsBefore >= 1, "the plot moved");
            assertTrue(plotPointsAfter - plotPointsBefore <= digestsAfter - digestsBefore + 1,
                    (plotPointsAfter - plotPointsBefore) + " plot points for " + (digestsAfter - digestsBefore) + " digests");
            long fieldTime = console.field().stores().latest().get(2, "demo.field").orElseThrow().timeMicros();
            assertTrue(fieldTime >= inPlay, "the field shows the digest's objects");
            assertFalse(streaming(console, 2, "demo.text"), "option data is not streamed during play");
            assertTrue(List.of("READY", "SET", "PLAYING").contains(console.field().robots().robot(2).orElseThrow().gameState()),
                    "the digest's Status reaches the Robots table");
            MatchDebugRule.Reading ok = console.field().matchRule().reading(2);
            assertTrue(ok.inPlay() && ok.warnings().isEmpty(), ok.describe());
            assertEquals(1, ok.fragments());

            // robot 3 sends two a period, robot 4 an over-size digest: both flagged
            Await.until("robot 3 flagged", () -> console.field().matchRule().reading(3).warnings().stream()
                    .anyMatch(w -> w.startsWith("too often")));
            Await.until("robot 4 flagged", () -> console.field().matchRule().reading(4).warnings().stream()
                    .anyMatch(w -> w.startsWith("too big")));
            Envelope bigDigest = heard.stream().filter(e -> e.robotId() == 4 && e.kind().equals("matchDigest"))
                    .reduce((a, b) -> b).orElseThrow();
            assertTrue(bigDigest.size() > 700 && bigDigest.size() <= 1400, bigDigest.size() + " bytes");
            assertTrue(bigDigest.extension(Fumanoid.matchDigest).getOmitted() > 0, "what does not fit is left out");
            // robot 5 chose nothing: its Status alone, once a period
            List<Envelope> five = datagrams(heard, 5, inPlay + PERIOD_MICROS);
            assertFalse(five.isEmpty());
            assertTrue(five.stream().allMatch(e -> e.kind().equals("status")), "robot 5 sends its Status alone");
            assertTrue(console.field().matchRule().reading(5).warnings().isEmpty(), console.field().matchRule().reading(5).describe());

            // after the game the robots stream again
            perform(gc, "finish");
            Await.until("demo.text streams again after the game", () -> streaming(console, 2, "demo.text"));
            Await.until("robot 2 out of play", () -> !console.field().matchRule().reading(2).inPlay());
        }
    }

    private static int rankOnRobot(Console console, int robot, String option) {
        return console.field().options().options(robot).option(option).map(OptionState::matchRankOnRobot).orElse(-1);
    }

    private static boolean streaming(Console console, int robot, String option) {
        return console.field().options().options(robot).option(option).map(OptionState::streaming).orElse(false);
    }

    private static long plotPoints(Console console, int robot) {
        var snapshot = console.field().stores().plots().snapshot(robot, "demo.plotter");
        return snapshot.series().isEmpty() ? 0 : snapshot.series().get(0).count();
    }
}
