package touchline.cli;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;
import touchline.testing.Await;
import touchline.testing.RobotProcess;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.net.ServerSocket;

import static org.junit.jupiter.api.Assertions.*;

/**
 * Issue 36, item 8: while {@code touchline serve} holds the robots' port, {@code touchline options
 * --connect} switches a real simulated robot's option through it (before: "port in use", and no
 * way through the serving console); without {@code --connect} the port-in-use sentence says how.
 */
@Tag("integration")
class OptionsThroughServeTest {

    @BeforeEach
    void needsBinary() {
        touchline.testing.Requirement.robotSide("touchline-robot");
    }

    private static int freeUdpPort() throws Exception {
        try (DatagramSocket s = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0))) {
            return s.getLocalPort();
        }
    }

    private static int freeTcpPort() throws Exception {
        try (ServerSocket s = new ServerSocket(0, 1, java.net.InetAddress.getLoopbackAddress())) {
            return s.getLocalPort();
        }
    }

    @Test
    void optionsSwitchesARobotsOptionThroughTheServingConsole() throws Exception {
        int robots = freeUdpPort();
        int web = freeTcpPort();
        StringWriter serveOut = new StringWriter();
        StringWriter serveErr = new StringWriter();
        int[] serveExit = {-1};
        Thread serve = new Thread(() -> {
            CommandLine cli = new CommandLine(new Main());
            cli.setOut(new PrintWriter(serveOut, true));
            cli.setErr(new PrintWriter(serveErr, true));
            serveExit[0] = cli.execute("serve", "--port", Integer.toString(web), "--robots-port", Integer.toString(robots),
                    "--robots-bind", "127.0.0.1", "--insecure", "--seconds", "120", "--stats-every", "60");
        }, "test-serve");
        serve.start();
        try {
            Await.until("serve is serving", () -> serveOut.toString().contains("ws://") || !serve.isAlive());
            assertTrue(serve.isAlive(), serveErr.toString());
            try (RobotProcess robot = RobotProcess.robot(5, robots).start()) {
                StringWriter err = new StringWriter();
                int inUse = Main.execute(new String[] {"options", "5", "--on", "demo.text", "--bind", "127.0.0.1",
                        "--port", Integer.toString(robots), "--timeout", "5"}, new PrintWriter(err, true));
                assertEquals(StartFailure.PORT_IN_USE, inUse, err.toString());
                assertTrue(err.toString().contains("--connect ws://127.0.0.1:8765/"), err.toString());

                err = new StringWriter();
                int code = Main.execute(new String[] {"options", "5", "--on", "demo.text",
                        "--connect", "ws://127.0.0.1:" + web + "/", "--timeout", "10"}, new PrintWriter(err, true));
                assertEquals(0, code, "through the serving console: " + err);

                err = new StringWriter();
                code = Main.execute(new String[] {"options", "5", "--on", "no.such.option",
                        "--connect", "ws://127.0.0.1:" + web + "/", "--timeout", "10"}, new PrintWriter(err, true));
                assertEquals(1, code, err.toString());

                // match mode's gate is the serving console's: a switch during play is held there
                try (touchline.app.Console viewer = new touchline.app.Console(touchline.app.ConsoleConfig.defaults()
                        .withGameControllerPort(0).withUdp(touchline.transport.UdpConfig.defaults()
                                .withBindAddress("127.0.0.1").withListenPort(0))).start();
                     DatagramSocket gc = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0))) {
                    viewer.remote().view(new java.net.URI("ws://127.0.0.1:" + web + "/"), null);
                    byte[] playing;
                    try (var in = OptionsThroughServeTest.class.getResourceAsStream("/golden/gamecontroller/hl12/04-playing.bin")) {
                        playing = in.readAllBytes();
                    }
                    gc.send(new java.net.DatagramPacket(playing, playing.length, java.net.InetAddress.getLoopbackAddress(),
                            robot.port()));
                    Await.until("the serving console heard the robot report PLAYING", () -> viewer.field().robots().robot(5)
                            .map(r -> r.gameState().equals("PLAYING")).orElse(false));
                    err = new StringWriter();
                    code = Main.execute(new String[] {"options", "5", "--on", "demo.plotter",
                            "--connect", "ws://127.0.0.1:" + web + "/", "--timeout", "10"}, new PrintWriter(err, true));
                    assertEquals(4, code, err.toString());
                    assertTrue(err.toString().contains("demo.plotter: held: ") && err.toString().contains("PLAYING"),
                            err.toString());
                }
            }
        } finally {
            serve.interrupt(); // serve waits for Ctrl+C or --seconds: an interrupt ends it as well
            serve.join();
        }
    }

    /**
     * A console that starts serving during play (the window's Ctrl+Shift+V in a game) never saw the
     * robot's option list, and the robot sends none in play: `options --connect` still asks the serving
     * console, whose match mode holds the switch, instead of waiting for a list that cannot come.
     */
    @Test
    void aSwitchAskedWhileTheRobotSendsOnlyItsStatusIsHeldNotLost() throws Exception {
        int robots = freeUdpPort();
        int web = freeTcpPort();
        StringWriter serveOut = new StringWriter();
        StringWriter serveErr = new StringWriter();
        Thread serve = new Thread(() -> {
            CommandLine cli = new CommandLine(new Main());
            cli.setOut(new PrintWriter(serveOut, true));
            cli.setErr(new PrintWriter(serveErr, true));
            cli.execute("serve", "--port", Integer.toString(web), "--robots-port", Integer.toString(robots),
                    "--robots-bind", "127.0.0.1", "--insecure", "--seconds", "120", "--stats-every", "60");
        }, "test-serve");
        serve.start();
        java.util.concurrent.ScheduledExecutorService robot = java.util.concurrent.Executors.newSingleThreadScheduledExecutor();
        try (DatagramSocket socket = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0))) {
            Await.until("serve is serving", () -> serveOut.toString().contains("ws://") || !serve.isAlive());
            assertTrue(serve.isAlive(), serveErr.toString());
            byte[] status = new touchline.protocol.FrameCodec().encode(touchline.protocol.Framing.LENGTH_PREFIX,
                    touchline.proto.Fumanoid.Message.newBuilder().setRobotID(9).setExtension(touchline.proto.Fumanoid.status,
                            touchline.proto.Fumanoid.Status.newBuilder().setTeamID(13).setGameState("PLAYING").build())
                            .build().toByteArray());
            // a robot in play: its Status once every 200 ms, nothing else
            robot.scheduleAtFixedRate(() -> {
                try {
                    socket.send(new java.net.DatagramPacket(status, status.length, java.net.InetAddress.getLoopbackAddress(), robots));
                } catch (java.io.IOException e) {
                    throw new java.io.UncheckedIOException(e);
                }
            }, 0, 200, java.util.concurrent.TimeUnit.MILLISECONDS);
            StringWriter err = new StringWriter();
            int code = Main.execute(new String[] {"options", "9", "--on", "demo.text",
                    "--connect", "ws://127.0.0.1:" + web + "/", "--timeout", "10"}, new PrintWriter(err, true));
            assertEquals(4, code, err.toString());
            assertTrue(err.toString().contains("demo.text: held: ") && err.toString().contains("PLAYING"), err.toString());
        } finally {
            robot.shutdownNow();
            serve.interrupt();
            serve.join();
        }
    }
}
