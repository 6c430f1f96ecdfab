package touchline.transport.nao;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.security.KeyDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.security.SecureRandom;
import java.time.Instant;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The encrypted NAO link for real: JeroMQ's CURVE client in the console against libzmq's CURVE
 * server and ZAP handler in the C++ {@code touchline-nao-sim} on loopback, with keys made by
 * {@link KeyDir} ({@code touchline keys new}, JeroMQ). With the right keys a call and a camera frame work; without a
 * key or with a key the robot was not given, no call is answered, no frame arrives, the link
 * says why, and the robot logs the refusal.
 */
@Tag("integration")
class NaoCurveRobotSideTest {

    @TempDir
    Path keys;
    @TempDir
    Path otherConsole;

    @BeforeAll
    static void needsBinary() {
        RobotSideProcess.assumeBuilt();
    }

    private RobotSideProcess secureSim() throws Exception {
        new KeyDir(keys).create(false, new SecureRandom(), Instant.now());
        return new RobotSideProcess(0, 0, "--curve-secret", keys.resolve("nao-server.secret").toString(),
                "--curve-clients", keys.resolve("console.public").toString());
    }

    @Test
    void rightKeysCallAndGetAFrame() throws Exception {
        try (RobotSideProcess sim = secureSim();
             NaoLink link = new NaoLink("127.0.0.1", sim.rpcPort, NaoLinkConfig.defaults(), e -> { },
                     NaoClientKeys.load(new KeyDir(keys)), new touchline.app.SystemClock(), new touchline.app.SystemClock()).start();
             NaoCameraStream camera = new NaoCameraStream("127.0.0.1", sim.camPort, e -> { }, NaoClientKeys.load(new KeyDir(keys)), new touchline.app.SystemClock(), new touchline.app.SystemClock()).start()) {
            assertTrue(Poll.until(() -> link.state() == ConnectionState.ONLINE), link.state()
                    + " " + link.securityProblem());
            assertEquals(new CallOutcome.Done(), link.call("ALTextToSpeech", "setVolume", 0.5f).get(20, TimeUnit.SECONDS));
            assertEquals(new CallOutcome.Value(0.5f), link.call("ALTextToSpeech", "getVolume").get(20, TimeUnit.SECONDS));
            try (AutoCloseable watching = camera.subscribe()) {
                assertTrue(Poll.until(() -> camera.latestFrame() != null), camera.lastError());
                assertTrue(camera.latestFrame().jpeg().length > 100);
            }
            assertTrue(sim.output.stream().anyMatch(l -> l.contains("CURVE on: 1 console key(s) allowed")), sim.output.toString());
        }
    }

    @Test
    void aConsoleKeyTheRobotWasNotGivenIsRefusedAndLogged() throws Exception {
        new KeyDir(otherConsole).create(false, new SecureRandom(), Instant.now());
        try (RobotSideProcess sim = secureSim()) {
            // the right server key, but a console key pair the robot does not know
            Files.copy(keys.resolve("nao-server.public"), otherConsole.resolve("nao-server.public"),
                    java.nio.file.StandardCopyOption.REPLACE_EXISTING);
            NaoClientKeys stranger = NaoClientKeys.load(new KeyDir(otherConsole));
            try (NaoLink link = new NaoLink("127.0.0.1", sim.rpcPort, NaoLinkConfig.defaults(), e -> { }, stranger, new touchline.app.SystemClock(), new touchline.app.SystemClock()).start();
                 NaoCameraStream camera = new NaoCameraStream("127.0.0.1", sim.camPort, e -> { }, stranger, new touchline.app.SystemClock(), new touchline.app.SystemClock()).start()) {
                assertTrue(Poll.until(() -> link.state() == ConnectionState.REFUSED),
                        link.state().toString());
                assertTrue(link.securityProblem().contains("the NAO refused our key: give it console.public"),
                        link.securityProblem());
                CallOutcome outcome = link.call("ALTextToSpeech", "getVolume").get(20, TimeUnit.SECONDS);
                assertInstanceOf(CallOutcome.Lost.class, outcome);
                try (AutoCloseable watching = camera.subscribe()) {
                    assertTrue(Poll.until(() -> camera.lastError() != null));
                    assertNull(camera.latestFrame());
                }
                assertEquals(0, link.stats().replies());
                assertTrue(Poll.until(() -> sim.output.stream().anyMatch(
                        l -> l.contains("rpc: refused a client without an allowed key from 127.0.0.1"))), sim.output.toString());
                assertTrue(Poll.until(() -> sim.output.stream().anyMatch(
                        l -> l.contains("camera: refused a client without an allowed key from 127.0.0.1"))), sim.output.toString());
            }
        }
    }

    @Test
    void anInsecureClientGetsNothing() throws Exception {
        try (RobotSideProcess sim = secureSim();
             NaoLink link = new NaoLink("127.0.0.1", sim.rpcPort, NaoLinkConfig.defaults(), e -> { }, null, new touchline.app.SystemClock(), new touchline.app.SystemClock()).start();
             NaoCameraStream camera = new NaoCameraStream("127.0.0.1", sim.camPort, e -> { }, null, new touchline.app.SystemClock(), new touchline.app.SystemClock()).start()) {
            CallOutcome outcome = link.call("ALTextToSpeech", "getVolume").get(20, TimeUnit.SECONDS);
            assertInstanceOf(CallOutcome.Lost.class, outcome);
            assertTrue(link.state() != ConnectionState.ONLINE);
            try (AutoCloseable watching = camera.subscribe()) {
                assertTrue(Poll.until(() -> camera.lastError() != null));
                assertNull(camera.latestFrame());
            }
            assertEquals(0, link.stats().replies());
        }
    }

    @Test
    void wrongServerKeyNeverGoesOnlineAndSaysWhy() throws Exception {
        try (RobotSideProcess sim = secureSim()) {
            new KeyDir(otherConsole).create(false, new SecureRandom(), Instant.now()); // another NAO's public key
            Files.copy(keys.resolve("console.secret"), otherConsole.resolve("console.secret"),
                    java.nio.file.StandardCopyOption.REPLACE_EXISTING);
            try (NaoLink link = new NaoLink("127.0.0.1", sim.rpcPort, NaoLinkConfig.defaults(), e -> { },
                    NaoClientKeys.load(new KeyDir(otherConsole)), new touchline.app.SystemClock(), new touchline.app.SystemClock()).start()) {
                assertTrue(Poll.until(() -> link.state() == ConnectionState.REFUSED),
                        link.state().toString());
                assertTrue(link.securityProblem().contains("no CURVE handshake"), link.securityProblem());
                assertEquals(0, link.stats().replies());
            }
        }
    }
}
