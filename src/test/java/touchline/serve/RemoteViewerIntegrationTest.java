package touchline.serve;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.app.Console;
import touchline.app.ConsoleConfig;
import touchline.model.OptionState;
import touchline.model.RobotSnapshot;
import touchline.model.store.TextLine;
import touchline.testing.Await;
import touchline.testing.Requirement;
import touchline.testing.RobotProcess;
import touchline.transport.Origin;
import touchline.transport.SendResult;
import touchline.transport.UdpConfig;
import touchline.transport.remote.RemoteStatus;

import java.net.URI;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/**
 * Touchline as a viewer, end to end: a simulated robot talks to a first Touchline that serves
 * its stream; a second Touchline connected to it shows the same robot, the same option tree and
 * the same debug text, refuses every command with the reason, and when the server goes away
 * says so and comes back by itself once it is there again.
 */
@Tag("integration")
class RemoteViewerIntegrationTest {

    private static final String TEXT = "demo.text";

    private static Console viewer() throws InterruptedException {
        return new Console(ConsoleConfig.defaults().withGameControllerPort(0)
                .withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0))).start();
    }

    private static List<String> optionNames(Console c, int robot) {
        return c.field().options().options(robot).options().stream().map(OptionState::name).sorted().toList();
    }

    private static List<String> texts(Console c, int robot) {
        return c.field().stores().live().text().since(-1, robot, 10_000).stream().map(e -> e.value().text()).toList();
    }

    @Test
    void aSecondTouchlineShowsTheSameRobotOptionsAndTextAndSendsNothing() throws Exception {
        Requirement.robotSide("touchline-robot");
        try (ServedField field = new ServedField();
             RobotProcess robot = RobotProcess.robot(4, field.console().field().port()).start();
             Console second = viewer()) {
            Console first = field.console();
            Await.until("the first console has robot 4's option list", () -> first.field().options().options(4).listReceived());
            second.remote().view(new URI(field.server().url("127.0.0.1")), null);
            Await.until("connected", () -> second.remote().stream().orElseThrow().status().state() == RemoteStatus.State.CONNECTED);
            assertTrue(first.optionSwitches().set(4, TEXT, true).isSent());
            // the robot sends its list again when an option changes, and its text from now on
            Await.until("robot 4 in the second console", () -> second.field().robots().robot(4).isPresent());
            Await.until("the same option tree", () -> !optionNames(second, 4).isEmpty()
                    && optionNames(second, 4).equals(optionNames(first, 4)));
            Await.until("debug text in the second console", () -> !texts(second, 4).isEmpty());
            List<String> seen = texts(second, 4);
            assertTrue(texts(first, 4).containsAll(seen), "every line the second shows, the first showed: " + seen);

            RobotSnapshot there = first.field().robots().robot(4).orElseThrow();
            RobotSnapshot here = second.field().robots().robot(4).orElseThrow();
            assertEquals(there.name(), here.name());
            assertEquals(there.teamId(), here.teamId());
            assertEquals(Origin.REMOTE, here.origin());
            assertTrue(second.field().options().options(4).option(TEXT).orElseThrow().enabledOnRobot());

            SendResult refused = second.optionSwitches().set(4, TEXT, false);
            assertFalse(refused.isSent());
            assertEquals(Console.COMMANDS_OFF, refused.reason());
            assertThrows(java.io.IOException.class, () -> second.referee().start(
                    new touchline.game.Game(touchline.game.LeagueParams.hlSimulationKidSize(), 4, 0, 5, 1,
                            new touchline.app.SystemClock()),
                    touchline.transport.gamecontroller.GcConfig.defaults(touchline.transport.gamecontroller.GcProfile.HL12)));
            assertEquals(0, second.field().transportCounts().datagramsOut(), "the viewing console sent nothing to any robot");
            assertTrue(first.field().options().options(4).option(TEXT).orElseThrow().wanted(), "the first console's wish stands");
        }
    }

    /**
     * Issue 36, item 8: a viewer shows the serving console's view of the options — on as the
     * robot says — not the local user's wanted file (before: those were wanted here, shown as
     * pending and "not seen yet" while the robot was online).
     */
    @Test
    void aViewerShowsTheServingConsolesOptionsNotItsOwnWantedFile(@org.junit.jupiter.api.io.TempDir java.nio.file.Path dir)
            throws Exception {
        Requirement.robotSide("touchline-robot");
        java.nio.file.Path wanted = dir.resolve("wanted-options.properties");
        java.nio.file.Files.writeString(wanted, "4/demo.plotter=on\n4/demo.table=on\n");
        try (ServedField field = new ServedField();
             RobotProcess robot = RobotProcess.robot(4, field.console().field().port()).start();
             Console second = viewer()) {
            Console first = field.console();
            Await.until("the first console has robot 4's option list", () -> first.field().options().options(4).listReceived());
            second.remote().view(new URI(field.server().url("127.0.0.1")), null);
            second.optionSwitches().rememberWanted(wanted); // as the window does after `console --connect`
            assertTrue(first.optionSwitches().set(4, TEXT, true).isSent());
            Await.until("demo.text on at the robot, as the viewer hears it", () -> second.field().options().options(4).option(TEXT)
                    .map(OptionState::enabledOnRobot).orElse(false));
            OptionState text = second.field().options().options(4).option(TEXT).orElseThrow();
            OptionState plotter = second.field().options().options(4).option("demo.plotter").orElseThrow();
            assertTrue(second.optionSwitches().shownOn(text), "on, as the serving console has it");
            assertFalse(plotter.wanted(), "the local wanted file is not this viewer's wish");
            assertFalse(second.optionSwitches().shownOn(plotter));
            assertFalse(first.field().options().options(4).option("demo.plotter").orElseThrow().enabledOnRobot());
            assertEquals(0, second.field().transportCounts().datagramsOut(), "the viewer sent nothing");
            assertEquals("4/demo.plotter=on\n4/demo.table=on\n", java.nio.file.Files.readString(wanted),
                    "the user's file is left as it was");
        }
    }

    /**
     * The demo runs with a team key, so the first console's robot datagrams carry a trailer: a
     * second Touchline still gets their messages (the served channel says the framing of the
     * frame before the trailer; before, it said neither framing nor schema and the viewer could
     * use none of the robots' channels).
     */
    @Test
    void aSecondTouchlineShowsTheRobotsOfAConsoleWithATeamKey() throws Exception {
        try (ServedField field = new ServedField(); Console second = viewer()) {
            second.remote().view(new URI(field.server().url("127.0.0.1")), null);
            Await.until("connected", () -> second.remote().stream().orElseThrow().status().state() == RemoteStatus.State.CONNECTED);
            long[] counter = {0};
            // a status each time the condition is polled: the viewer subscribes once the channel is advertised
            Await.until("robot 6 in the second console", () -> {
                field.publishTagged(ServedField.status(6, "tagged-six", 77), "status", ++counter[0]);
                return second.field().robots().robot(6).isPresent();
            });
            RobotSnapshot here = second.field().robots().robot(6).orElseThrow();
            assertEquals("tagged-six", here.name());
            assertEquals(Origin.REMOTE, here.origin());
            assertEquals(0, second.remote().stream().orElseThrow().status().unusable(),
                    second.remote().stream().orElseThrow().status().toString());
        }
    }

    private static void send(java.net.DatagramSocket s, java.net.DatagramPacket p) {
        try {
            s.send(p);
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    @Test
    void theGameControllerAndMalformedDatagramsReachTheViewerAndItsMatchModeFollowsTheRemoteField() throws Exception {
        try (ServedField field = new ServedField(); Console second = viewer()) {
            java.util.List<touchline.transport.Envelope> heard = new java.util.concurrent.CopyOnWriteArrayList<>();
            try (AutoCloseable sub = second.field().bus().subscribe(heard::add)) {
                second.remote().view(new URI(field.server().url("127.0.0.1")), null);
                Await.until("connected", () -> second.remote().stream().orElseThrow().status().state() == RemoteStatus.State.CONNECTED);
                assertFalse(second.referee().matchMode().playIsOn());
                byte[] playing;
                try (var in = RemoteViewerIntegrationTest.class.getResourceAsStream("/golden/gamecontroller/hl12/04-playing.bin")) {
                    playing = in.readAllBytes();
                }
                Await.until("the GameController's packet on the viewer", () -> {
                    // as the first console's port watch publishes what it hears on 3838 (the raw channel appears with it)
                    field.console().field().bus().accept(new touchline.transport.Envelope(field.console().field().clock().nowMicros(),
                            touchline.transport.Direction.IN, touchline.transport.Channel.GAMECONTROLLER,
                            new java.net.InetSocketAddress("127.0.0.1", 3838), touchline.transport.Envelope.NO_ROBOT,
                            "gc.hl12", null, playing, null));
                    return heard.stream().anyMatch(e -> e.channel() == touchline.transport.Channel.GAMECONTROLLER);
                });
                touchline.transport.Envelope gc = heard.stream()
                        .filter(e -> e.channel() == touchline.transport.Channel.GAMECONTROLLER).findFirst().orElseThrow();
                org.junit.jupiter.api.Assertions.assertArrayEquals(playing, gc.raw(), "the datagram's bytes as heard there");
                assertEquals("gc.hl12", gc.kind());
                assertEquals(Origin.REMOTE, gc.origin());
                Await.until("the viewer's match mode shows the remote field's play", () -> second.referee().matchMode().playIsOn());
                assertTrue(second.referee().matchMode().notice().contains("remote console's GameController"),
                        second.referee().matchMode().notice());

                // a datagram the first console could not decode: the viewer's network console shows the same error
                byte[] garbage = {1, 2, 3, 4, 5, 6, 7};
                try (java.net.DatagramSocket s = new java.net.DatagramSocket()) {
                    Await.until("the malformed datagram on the viewer", () -> {
                        send(s, new java.net.DatagramPacket(garbage, garbage.length,
                                java.net.InetAddress.getLoopbackAddress(), field.console().field().port()));
                        return heard.stream().anyMatch(e -> e.error() != null);
                    });
                }
                touchline.transport.Envelope bad = heard.stream().filter(e -> e.error() != null).findFirst().orElseThrow();
                org.junit.jupiter.api.Assertions.assertArrayEquals(garbage, bad.raw());
                assertFalse(bad.error().isEmpty());
                assertEquals(0, second.field().transportCounts().datagramsOut(), "the viewing console sent nothing");
            }
        }
    }

    @Test
    void aLostServerIsSaidAndTheViewerReconnectsAndSubscribesAgain() throws Exception {
        try (ServedField field = new ServedField(); Console second = viewer()) {
            int port = field.server().port();
            second.remote().view(new URI(field.server().url("127.0.0.1")), null);
            field.publish(ServedField.text(2, "a", "before"), "debugText");
            Await.until("first text", () -> {
                field.publish(ServedField.text(2, "a", "before"), "debugText");
                return texts(second, 2).contains("before");
            });
            field.server().close();
            Await.until("lost", () -> second.remote().stream().orElseThrow().status().state() == RemoteStatus.State.LOST);
            assertTrue(second.remote().stream().orElseThrow().status().describe().contains("reconnecting"));
            try (FoxgloveServer again = new FoxgloveServer(ServeConfig.defaults().withPort(port),
                    field.console().field().kinds(), field.console().field().clock()).start();
                 AutoCloseable sub = field.console().field().bus().subscribe(again)) {
                Await.until("reconnected and subscribed", () -> {
                    field.publish(ServedField.text(2, "a", "after"), "debugText");
                    return texts(second, 2).contains("after");
                });
                assertEquals(RemoteStatus.State.CONNECTED, second.remote().stream().orElseThrow().status().state());
            }
        }
    }

    @Test
    void aWrongTokenIsAStatusNotACrash() throws Exception {
        try (ServedField field = new ServedField(ServeConfig.defaults().withPort(0).withToken("right"));
             Console second = viewer()) {
            second.remote().view(new URI("ws://127.0.0.1:" + field.server().port() + "/?token=wrong"), null);
            Await.until("refused", () -> second.remote().stream().orElseThrow().status().detail().contains("token"));
            assertEquals(RemoteStatus.State.LOST, second.remote().stream().orElseThrow().status().state());
        }
    }

    @Test
    void whatTheServerSaidBeforeClosingIsShown() throws Exception {
        try (ServedField field = new ServedField(ServeConfig.defaults().withPort(0).withMaxViewers(0));
             Console second = viewer()) {
            second.remote().view(new URI(field.server().url("127.0.0.1")), null);
            Await.until("told why", () -> second.remote().stream().orElseThrow().status().state() == RemoteStatus.State.LOST
                    && second.remote().stream().orElseThrow().status().detail().contains("too many viewers"));
            assertTrue(second.remote().stream().orElseThrow().status().describe().contains("reconnecting"));
        }
    }
}
