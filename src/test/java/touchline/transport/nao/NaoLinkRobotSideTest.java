package touchline.transport.nao;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.protocol.nao.NaoModules;
import touchline.transport.Envelope;

import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * NaoLink and the camera stream against the real C++ {@code touchline-nao-sim} on loopback
 * (OS-chosen ports). Skipped when the robot side is not built.
 */
@Tag("integration")
class NaoLinkRobotSideTest {

    private final List<Envelope> envelopes = new CopyOnWriteArrayList<>();

    @BeforeAll
    static void needsBinary() {
        RobotSideProcess.assumeBuilt();
    }

    private static CallOutcome get(CompletableFuture<CallOutcome> f) throws Exception {
        return f.get(20, TimeUnit.SECONDS);
    }

    private NaoLink online(RobotSideProcess sim) throws Exception {
        NaoLink link = new NaoLink("127.0.0.1", sim.rpcPort, NaoLinkConfig.defaults(), envelopes::add, null, new touchline.app.SystemClock(), new touchline.app.SystemClock()).start();
        assertTrue(Poll.until(() -> link.state() == ConnectionState.ONLINE), "online");
        return link;
    }

    @Test
    void valuesVoidErrorsAndDiscovery() throws Exception {
        try (RobotSideProcess sim = new RobotSideProcess(0, 0); NaoLink link = online(sim)) {
            assertEquals(new CallOutcome.Done(), get(link.call("ALTextToSpeech", "setVolume", 0.25f)));
            CallOutcome volume = get(link.call("ALTextToSpeech", "getVolume"));
            assertEquals(new CallOutcome.Value(0.25f), volume);
            assertEquals(new CallOutcome.Done(), get(link.call("ALMemory", "insertData", "Touchline/test", "hello")));
            assertEquals(new CallOutcome.Value("hello"), get(link.call("ALMemory", "getData", "Touchline/test")));
            assertInstanceOf(CallOutcome.Failed.class, get(link.call("NoSuchModule", "ping")));
            assertInstanceOf(CallOutcome.Failed.class, get(link.call("ALMotion", "noSuchMethod")));
            CallOutcome modules = get(link.call(NaoModules.ROBOT_SIDE, "getModuleList"));
            assertInstanceOf(CallOutcome.Value.class, modules);
            assertEquals(new java.util.TreeSet<>(NaoModules.ALL),
                    new java.util.TreeSet<>((List<?>) ((CallOutcome.Value) modules).value()), "the one module list is the robot side's");
            for (String module : NaoModules.ALL) {
                CallOutcome methods = get(link.call(module, "getMethodList"));
                assertInstanceOf(CallOutcome.Value.class, methods, module);
                Object list = ((CallOutcome.Value) methods).value();
                assertTrue(list instanceof List<?> l && l.contains("getMethodList"), module + ": " + list);
            }
            SequenceOutcome stand = new NaoMoves(link).stand().get(30, TimeUnit.SECONDS);
            assertTrue(stand.ok(), stand.describe());
            assertEquals(new CallOutcome.Value("Standing"), get(link.call("ALRobotPosture", "getPostureFamily")));
            SequenceOutcome bad = link.sequence(List.of(NaoCall.of("ALRobotPosture", "goToPosture", "NoSuchPosture", 1.0f),
                    NaoCall.of("ALMemory", "insertData", "Touchline/after", 1))).get(30, TimeUnit.SECONDS);
            assertEquals(0, bad.failedIndex(), bad.describe());
            assertInstanceOf(CallOutcome.Failed.class, get(link.call("ALMemory", "getData", "Touchline/after")),
                    "the step after the failure must not have run");
        }
    }

    @Test
    void aKilledServerIsLostWithin3sAndNothingRunsLateAfterItRestarts() throws Exception {
        RobotSideProcess sim = new RobotSideProcess(0, 0);
        int port = sim.rpcPort;
        try (NaoLink link = online(sim)) {
            CompletableFuture<CallOutcome> inFlight = link.call(NaoCall.of("ALRobotPosture", "goToPosture", "Sit", 0.2f));
            sim.kill();
            // how fast a loss is noticed is a budget (docs/benchmarks.md), not asserted here
            assertTrue(Poll.until(() -> link.state() == ConnectionState.LOST), "lost");
            assertInstanceOf(CallOutcome.Lost.class, get(inFlight));
            assertInstanceOf(CallOutcome.Lost.class, get(link.call("ALMemory", "insertData", "Touchline/late", 1)));

            sim = new RobotSideProcess(port, 0);
            RobotSideProcess restarted = sim;
            assertTrue(Poll.until(() -> link.state() == ConnectionState.ONLINE), "back online");
            Thread.sleep(500); // nothing to await: a late delivery would arrive now if anything were queued
            assertInstanceOf(CallOutcome.Failed.class, get(link.call("ALMemory", "getData", "Touchline/late")),
                    "the call made while the robot was down must not run after it restarts");
            assertEquals(port, restarted.rpcPort);
            CallOutcome log = get(link.call("Robot", "getCallLog"));
            assertInstanceOf(CallOutcome.Value.class, log);
            assertTrue(((List<?>) ((CallOutcome.Value) log).value()).stream()
                    .noneMatch(entry -> String.valueOf(entry).contains("insertData")), "call log: " + log.describe());
        } finally {
            sim.close();
        }
    }

    @Test
    void aFrozenServerIsLostByHeartbeatAndItsLateCallIsNotRunWhenItThaws() throws Exception {
        try (RobotSideProcess sim = new RobotSideProcess(0, 0); NaoLink link = online(sim)) {
            sim.freeze();
            long frozen = System.nanoTime();
            // Sent into the frozen robot's socket buffer: only its deadline keeps it from running later.
            CompletableFuture<CallOutcome> intoTheFreeze = link.call(NaoCall.of("ALMemory", "insertData", "Touchline/frozen", 1), 1000);
            assertTrue(Poll.until(() -> link.state() == ConnectionState.LOST), "lost");
            long detectedMs = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - frozen);
            CallOutcome outcome = get(intoTheFreeze);
            assertTrue(outcome instanceof CallOutcome.Lost || outcome instanceof CallOutcome.TimedOut, outcome.describe());
            Thread.sleep(1200); // nothing to await: let the call's deadline pass before the robot thaws
            sim.signal("CONT");
            assertTrue(Poll.until(() -> link.state() == ConnectionState.ONLINE), "back online");
            assertInstanceOf(CallOutcome.Failed.class, get(link.call("ALMemory", "getData", "Touchline/frozen")),
                    "a call stuck in a frozen robot must not run after its deadline (detected after " + detectedMs + " ms)");
        }
    }

    @Test
    void hugeAndDeepParametersAreClearErrorsAndTheLinkGoesOn() throws Exception {
        try (RobotSideProcess sim = new RobotSideProcess(0, 0); NaoLink link = online(sim)) {
            CallOutcome huge = get(link.call(NaoCall.of("ALMemory", "insertData", "Touchline/big", new byte[50_000_000]), 20_000));
            assertInstanceOf(CallOutcome.Failed.class, huge);
            Object deep = "x";
            for (int i = 0; i < 40; i++) {
                deep = List.of(deep);
            }
            CallOutcome tooDeep = get(link.call("ALMemory", "insertData", "Touchline/deep", deep));
            assertInstanceOf(CallOutcome.Failed.class, tooDeep);
            assertTrue(tooDeep.describe().contains("deeper"), tooDeep.describe());
            assertEquals(new CallOutcome.Value(true), get(link.call("ALMotion", "ping")));
        }
    }

    @Test
    void cameraConfigureAndFetch() throws Exception {
        try (RobotSideProcess sim = new RobotSideProcess(0, 0);
             NaoCameraStream camera = new NaoCameraStream("127.0.0.1", sim.camPort, envelopes::add, null, new touchline.app.SystemClock(), new touchline.app.SystemClock()).start()) {
            camera.configure(new CameraSettings(2, 11, 30));
            try (AutoCloseable viewer = camera.subscribe()) {
                assertTrue(Poll.until(() -> camera.framesReceived() >= 5), "" + camera.lastError());
                assertEquals(640, camera.latestFrame().width());
                assertEquals(480, camera.latestFrame().height());
                camera.configure(new CameraSettings(1, 11, 30));
                assertTrue(Poll.until(() -> camera.latestFrame().width() == 320));
            }
        }
    }

    @Test
    void quickCallsAnswerWhileEveryWorkerIsBlockedAndBadOnesGetClearErrors() throws Exception {
        try (RobotSideProcess sim = new RobotSideProcess(0, 0, "--workers", "2"); NaoLink link = online(sim)) {
            String text = "This keeps a worker busy. ".repeat(40); // 60 ms a character: about a minute
            List<CompletableFuture<CallOutcome>> says = List.of(
                    link.call(NaoCall.of("ALTextToSpeech", "say", text), 120_000),
                    link.call(NaoCall.of("ALTextToSpeech", "say", text), 120_000));
            assertTrue(Poll.until(() -> {
                CallOutcome log = link.call("Robot", "getCallLog").join();
                return log instanceof CallOutcome.Value v && v.value().toString().split("ALTextToSpeech.say", -1).length == 3;
            }), "both workers run a say");
            // answered while both minute-long says hold the workers (their latency is benchmarked)
            for (int i = 0; i < 20; i++) {
                assertEquals(new CallOutcome.Value(true), get(link.call("ALMotion", "ping")), "ping " + i);
            }
            CallOutcome extra = get(link.call("ALMotion", "ping", 1));
            assertTrue(extra instanceof CallOutcome.Failed f && f.error().contains("expected 0 parameters, got 1"),
                    extra.describe());
            CallOutcome stats = get(link.call("Robot", "getRpcStats"));
            assertTrue(stats.describe().contains("inlineCalls"), stats.describe());
            assertFalse(says.get(0).isDone() || says.get(1).isDone(), "the says were still running");
            assertEquals(new CallOutcome.Done(), get(link.call("ALTextToSpeech", "stopAll")));
            assertEquals(new CallOutcome.Done(), get(says.get(0)));
            assertEquals(new CallOutcome.Done(), get(says.get(1)));
        }
    }
}
