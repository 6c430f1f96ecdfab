package touchline.app;

import touchline.testing.Await;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.model.OptionState;
import touchline.model.RobotSnapshot;
import touchline.proto.Fumanoid;
import touchline.testing.RobotProcess;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.UdpConfig;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import static org.junit.jupiter.api.Assertions.*;

/**
 * The whole path of issue 2 with real parts: the C simulated robot on loopback, the Netty
 * pipeline, the model. Kills the robot and restarts it: the option that was on comes back on
 * without anyone asking.
 */
@Tag("integration")
class SimulatedRobotIntegrationTest {

    private final List<Envelope> seen = new CopyOnWriteArrayList<>();

    @BeforeEach
    void needsBinary() {
        touchline.testing.Requirement.robotSide("touchline-robot");
    }


    private long dataFrom(int robot, String option) {
        return seen.stream().filter(e -> e.direction() == Direction.IN && e.robotId() == robot
                && e.message() instanceof Fumanoid.Message m && m.hasExtension(Fumanoid.debugText)
                && m.getExtension(Fumanoid.debugText).getOption().equals(option)).count();
    }

    @Test
    void robotAppearsStreamsAnOptionGoesOfflineAndGetsItsOptionBackAfterRestart() throws Exception {
        ConsoleConfig config = ConsoleConfig.defaults()
                .withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0));
        try (Console console = new Console(config).start()) {
            console.field().bus().subscribe(seen::add);
            int port = console.field().port();
            RobotProcess robot = RobotProcess.robot(7, port).start();
            try {
                Await.until("robot 7 appears", () -> console.field().robots().robot(7).map(RobotSnapshot::online).orElse(false));
                RobotSnapshot r = console.field().robots().robot(7).orElseThrow();
                assertEquals(13, r.teamId());
                assertFalse(r.role().isEmpty(), "the keep-alive carries a role");

                Await.until("option list", () -> console.field().options().options(7).listReceived());
                List<String> names = console.field().options().options(7).options().stream().map(OptionState::name).toList();
                assertTrue(names.containsAll(List.of("demo.text", "demo.plotter", "demo.table", "demo.image",
                        "demo.relative", "demo.field", "havimo.region", "havimo.grid")), names.toString());
                assertEquals(0, dataFrom(7, "demo.text"), "nothing streams before it is switched on");

                assertTrue(console.optionSwitches().set(7, "demo.text", true).isSent());
                Await.until("demo.text data", () -> dataFrom(7, "demo.text") > 0);

                robot.kill();
                Await.until("robot 7 offline", () -> !console.field().robots().robot(7).orElseThrow().online());
                long requestsBefore = seen.stream().filter(e -> e.direction() == Direction.OUT
                        && e.kind().equals("debugOptionRequest")).count();
                seen.clear();

                robot = RobotProcess.robot(7, port).start(); // a fresh process: it knows nothing of demo.text
                Await.until("robot 7 back online", () -> console.field().robots().robot(7).orElseThrow().online());
                Await.until("demo.text streams again without being asked", () -> dataFrom(7, "demo.text") > 0);
                assertTrue(seen.stream().anyMatch(e -> e.direction() == Direction.OUT && e.kind().equals("debugOptionRequest")),
                        "the console re-sent the request by itself");
                assertTrue(requestsBefore >= 1);
                assertTrue(console.field().options().wanted(7).contains("demo.text"));
            } finally {
                robot.close();
            }
        }
    }

    @Test
    void aTeamOfThreeAppearsWithLengthAndLegacyFraming() throws Exception {
        ConsoleConfig config = ConsoleConfig.defaults()
                .withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0));
        try (Console console = new Console(config).start()) {
            int port = console.field().port();
            try (RobotProcess r1 = RobotProcess.robot(1, port, "--framing", "legacy").start();
                 RobotProcess r2 = RobotProcess.robot(2, port, "--framing", "length").start();
                 RobotProcess r3 = RobotProcess.robot(3, port).start()) {
                Await.until("three robots online", () -> console.field().robots().robots().stream().filter(RobotSnapshot::online).count() == 3);
                Await.until("all option lists", () -> console.field().options().options(1).listReceived()
                        && console.field().options().options(2).listReceived() && console.field().options().options(3).listReceived());
                assertEquals(0, console.field().transportCounts().malformedIn());
            }
        }
    }

    /** The demo's configuration: the firmware core behind the simulated GS1500M serial Wi-Fi module. */
    @Test
    void firmwareBehindTheSimulatedWifiModuleStreamsAnOption() throws Exception {
        ConsoleConfig config = ConsoleConfig.defaults()
                .withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0));
        try (Console console = new Console(config).start()) {
            console.field().bus().subscribe(seen::add);
            try (RobotProcess robot = RobotProcess.robot(9, console.field().port(), "--wifi-sim").start()) {
                Await.until("robot 9 and its option list", () -> console.field().options().options(9).listReceived());
                assertTrue(console.optionSwitches().set(9, "demo.text", true).isSent());
                Await.until("demo.text data through the serial module", () -> dataFrom(9, "demo.text") > 0);
                assertEquals(0, console.field().transportCounts().malformedIn());
            }
        }
    }
}
