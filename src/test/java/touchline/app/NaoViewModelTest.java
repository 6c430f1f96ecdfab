package touchline.app;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.testing.Await;
import touchline.transport.Origin;
import touchline.transport.UdpConfig;
import touchline.transport.nao.FakeNaoCamera;
import touchline.transport.nao.FakeNaoRobot;

import java.net.URI;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.*;

/**
 * The NAO view's model without a window: against the in-test robot and camera stand-ins, on a
 * console that views a remote Touchline, and with nothing connected.
 */
class NaoViewModelTest {

    private static Console console() {
        return new Console(ConsoleConfig.defaults().withGameControllerPort(0)
                .withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0)));
    }

    @Test
    void connectsDiscoversCallsAndShowsTheFramesOfTheConsolesStream() throws Exception {
        try (FakeNaoRobot robot = new FakeNaoRobot(0); FakeNaoCamera camera = new FakeNaoCamera();
             Console console = console(); NaoViewModel nao = new NaoViewModel(console.naos())) {
            nao.setResolution(1);
            nao.showCamera(true);
            assertTrue(nao.connect("127.0.0.1", " " + robot.port(), Integer.toString(camera.port()), "unused", true),
                    nao.result());
            assertTrue(nao.connected());
            Await.until("online", () -> nao.state().startsWith("online (INSECURE)"));
            nao.discover("Test");
            Await.until("the methods", () -> nao.methods().contains("echo"));
            assertEquals(1, nao.methodsVersion());
            nao.call("Test", "echo", "[a, 1]");
            Await.until("the echo", () -> nao.result().equals("Test.echo: [\"a\", 1]"));
            Await.until("a frame", () -> nao.frame().isPresent());
            assertEquals(320, nao.frame().orElseThrow().width(), "the resolution asked for before connecting");
            assertTrue(nao.cameraFigures().contains("B/frame"), nao.cameraFigures());
            nao.disconnect();
            assertFalse(nao.connected());
            assertEquals("not connected", nao.state());
            assertTrue(console.naos().sessions().isEmpty(), "the console forgot the session");
        }
    }

    @Test
    void withNothingConnectedItSaysSoAndTellsABadParameterFirst() throws Exception {
        try (Console console = console(); NaoViewModel nao = new NaoViewModel(console.naos())) {
            nao.stand();
            assertEquals("not connected", nao.result());
            nao.call("ALMotion", null, "");
            assertEquals("choose a method (\"Methods\" lists them)", nao.result());
            nao.call("ALMotion", "setAngles", "[HeadYaw, 0.5");
            assertFalse(nao.result().isEmpty());
            assertNotEquals("not connected", nao.result(), "the parse error, not the missing NAO");
            assertFalse(nao.walkKey('X', true), "not a walk key");
            assertTrue(nao.walkKey('W', true));
            assertEquals("walk: not connected", nao.result());
            assertFalse(nao.connect("127.0.0.1", "55x", "0", "unused", true));
            assertTrue(nao.result().startsWith("bad port"), nao.result());
        }
    }

    @Test
    void onAViewerEveryCommandIsRefusedAndTheRemoteFramesAreShown() throws Exception {
        try (Console console = console(); NaoViewModel nao = new NaoViewModel(console.naos())) {
            console.remote().view(new URI("ws://127.0.0.1:9/"), null); // nobody there: it only has to be a viewer
            assertFalse(nao.connect("127.0.0.1", "5555", "5556", "unused", true));
            assertEquals(Console.COMMANDS_OFF, nao.result());
            assertTrue(console.naos().sessions().isEmpty());
            nao.call("ALMotion", "wakeUp", "");
            assertEquals(Console.COMMANDS_OFF, nao.result());
            nao.say("hi");
            assertEquals(Console.COMMANDS_OFF, nao.result());
            assertTrue(nao.walkKey('Q', true));
            assertEquals("walk: " + Console.COMMANDS_OFF, nao.result());
            assertTrue(nao.state().startsWith("viewing a remote Touchline"), nao.state());

            byte[] jpeg = touchline.testing.NaoCameraEnvelopes.jpeg(160, 120);
            console.field().bus().accept(touchline.testing.NaoCameraEnvelopes.frame(jpeg, 42, Origin.REMOTE));
            assertArrayEquals(jpeg, nao.frame().orElseThrow().jpeg());
        }
    }

    @Test
    void onAViewerTheRemoteConsolesNaoCallsAndTheirOutcomesAreTheResultLine() throws Exception {
        try (Console console = console(); NaoViewModel nao = new NaoViewModel(console.naos())) {
            console.remote().view(new URI("ws://127.0.0.1:9/"), null); // nobody there: it only has to be a viewer
            assertEquals("", nao.result());
            touchline.proto.Nao.HAWActorRPCResponse volume = touchline.proto.Nao.HAWActorRPCResponse.newBuilder()
                    .setReturnval(new touchline.protocol.nao.MixedValueCodec().encode(80L)).build();
            console.field().bus().accept(new touchline.transport.Envelope(1, touchline.transport.Direction.IN,
                    touchline.transport.Channel.NAO_RPC, touchline.testing.NaoCameraEnvelopes.CAMERA,
                    touchline.transport.Envelope.NO_ROBOT, "ALTextToSpeech.getVolume", volume, volume.toByteArray(),
                    null, Origin.REMOTE));
            assertEquals("ALTextToSpeech.getVolume: 80", nao.result());
            nao.stand();
            assertEquals(Console.COMMANDS_OFF, nao.result(), "the view's own refusal is newer");
            console.field().bus().accept(new touchline.transport.Envelope(2, touchline.transport.Direction.IN,
                    touchline.transport.Channel.NAO_RPC, touchline.testing.NaoCameraEnvelopes.CAMERA,
                    touchline.transport.Envelope.NO_ROBOT, "ALMotion.wakeUp",
                    touchline.proto.Nao.HAWActorRPCResponse.getDefaultInstance(), new byte[0], null, Origin.REMOTE));
            assertEquals("ALMotion.wakeUp: done", nao.result(), "a newer remote outcome");
        }
    }

    @Test
    void aReplayedNaoCameraIsShownWhileTheReplayIsOpen(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("nao.mcap");
        byte[] last = touchline.testing.NaoCameraEnvelopes.jpeg(320, 240);
        try (Console recording = console()) {
            recording.recordings().start(file);
            long t = recording.field().clock().nowMicros();
            recording.field().bus().accept(touchline.testing.NaoCameraEnvelopes.frame(
                    touchline.testing.NaoCameraEnvelopes.jpeg(160, 120), t, Origin.LIVE));
            recording.field().bus().accept(touchline.testing.NaoCameraEnvelopes.frame(last, t + 66_000, Origin.LIVE));
            recording.recordings().stop();
        }
        try (Console console = console(); NaoViewModel nao = new NaoViewModel(console.naos())) {
            Replay replay = console.replays().open(file);
            assertTrue(nao.frame().isEmpty(), "nothing played yet");
            assertEquals(2, replay.runFor(100));
            NaoFrame shown = nao.frame().orElseThrow();
            assertArrayEquals(last, shown.jpeg(), "the recording's newest frame");
            assertEquals(240, shown.height());
            console.replays().close();
            assertTrue(nao.frame().isEmpty(), "the replay's frames went with it; no live NAO");
        }
    }

    @Test
    void aReplayedNaoCallIsTheResultLineWhileTheReplayIsOpen(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("calls.mcap");
        touchline.proto.Nao.HAWActorRPCResponse error = touchline.proto.Nao.HAWActorRPCResponse.newBuilder()
                .setError("ALMotion has no method fly").build();
        try (Console recording = console()) {
            recording.recordings().start(file);
            recording.field().bus().accept(new touchline.transport.Envelope(recording.field().clock().nowMicros(),
                    touchline.transport.Direction.IN, touchline.transport.Channel.NAO_RPC,
                    touchline.testing.NaoCameraEnvelopes.CAMERA, touchline.transport.Envelope.NO_ROBOT, "ALMotion.fly",
                    error, error.toByteArray(), null, Origin.LIVE));
            recording.recordings().stop();
        }
        try (Console console = console(); NaoViewModel nao = new NaoViewModel(console.naos())) {
            Replay replay = console.replays().open(file);
            assertEquals("", nao.result(), "nothing played yet");
            assertEquals(1, replay.runFor(100));
            assertEquals("ALMotion.fly: error: ALMotion has no method fly", nao.result());
            console.replays().close();
            assertEquals("", nao.result(), "the replay's calls went with it");
        }
    }
}
