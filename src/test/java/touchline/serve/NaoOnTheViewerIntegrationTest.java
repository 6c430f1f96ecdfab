package touchline.serve;

import com.google.protobuf.ByteString;
import com.google.protobuf.DynamicMessage;
import org.json.JSONObject;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.app.Console;
import touchline.app.ConsoleConfig;
import touchline.testing.Await;
import touchline.testing.Requirement;
import touchline.testing.RobotProcess;
import touchline.transport.Channel;
import touchline.transport.Envelope;
import touchline.transport.Origin;
import touchline.transport.UdpConfig;
import touchline.transport.nao.CallOutcome;
import touchline.transport.nao.CameraSettings;
import touchline.transport.nao.NaoCameraStream;
import touchline.transport.nao.NaoLink;
import touchline.transport.nao.NaoLinkConfig;

import java.net.URI;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import static org.junit.jupiter.api.Assertions.*;

/**
 * The NAO on the viewers: the simulated NAO ({@code touchline-nao-sim}) talks to a first
 * Touchline through a real {@link NaoLink} and {@link NaoCameraStream} publishing into its
 * Envelope stream; that console serves. A Foxglove client gets the camera's frames as
 * {@code foxglove.CompressedImage} on {@code /nao/camera/image}, and a second Touchline
 * viewing the first gets the NAO's calls, replies and frames as envelopes, with the bytes the
 * first one saw.
 */
@Tag("integration")
class NaoOnTheViewerIntegrationTest {

    private static final Pattern CAMERA_PORT = Pattern.compile("camera listening on port (\\d+)");

    /** The simulated NAO with a link and a camera stream publishing into {@code console}'s stream. */
    private record Nao(RobotProcess sim, NaoLink link, NaoCameraStream camera, AutoCloseable watching)
            implements AutoCloseable {
        @Override
        public void close() throws Exception {
            watching.close();
            camera.close();
            link.close();
            sim.close();
        }
    }

    /** Everything NAO-specific of this test; the NAO helper's API may rename it, so it lives here only. */
    private static Nao nao(Console console) throws Exception {
        RobotProcess sim = sim();
        int[] ports = simPorts(sim);
        NaoLink link = new NaoLink("127.0.0.1", ports[0], NaoLinkConfig.defaults(), console.field().bus(), null, new touchline.app.SystemClock(), new touchline.app.SystemClock()).start();
        NaoCameraStream camera = new NaoCameraStream("127.0.0.1", ports[1], console.field().bus(), null, new touchline.app.SystemClock(), new touchline.app.SystemClock()).start();
        camera.configure(new CameraSettings(1, 11, 30));
        return new Nao(sim, link, camera, camera.subscribe());
    }

    /**
     * A served console with the NAO view's model, the simulated NAO (not connected yet: its
     * {@code ports}, RPC and camera), and a second Touchline viewing the first with its own NAO view.
     */
    private record NaoViews(ServedField field, RobotProcess sim, int[] ports, touchline.app.NaoViewModel first,
                            Console second, touchline.app.NaoViewModel viewing) implements AutoCloseable {

        static NaoViews open() throws Exception {
            ServedField field = new ServedField();
            RobotProcess sim = null;
            Console second = null;
            try {
                sim = NaoOnTheViewerIntegrationTest.sim();
                int[] ports = simPorts(sim);
                second = viewer();
                second.remote().view(new URI(field.server().url("127.0.0.1")), null);
                return new NaoViews(field, sim, ports, new touchline.app.NaoViewModel(field.console().naos()), second,
                        new touchline.app.NaoViewModel(second.naos()));
            } catch (Exception | AssertionError e) {
                if (second != null) {
                    second.close();
                }
                if (sim != null) {
                    sim.close();
                }
                field.close();
                throw e;
            }
        }

        @Override
        public void close() throws Exception {
            viewing.close();
            second.close();
            first.close();
            sim.close();
            field.close();
        }
    }

    private static RobotProcess sim() throws Exception {
        return RobotProcess.of(List.of(RobotProcess.binDir().resolve("touchline-nao-sim").toString(),
                "--bind", "127.0.0.1", "--rpc-port", "0", "--cam-port", "0")).start();
    }

    private static Console viewer() throws InterruptedException {
        return new Console(ConsoleConfig.defaults().withGameControllerPort(0)
                .withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0))).start();
    }

    /** The simulated NAO, started, and its camera port. */
    private static int[] simPorts(RobotProcess sim) throws Exception {
        Await.until("the camera's port", () -> CAMERA_PORT.matcher(sim.stdout()).find());
        Matcher m = CAMERA_PORT.matcher(sim.stdout());
        assertTrue(m.find());
        return new int[]{sim.port(), Integer.parseInt(m.group(1))};
    }

    private static boolean naoFrame(Envelope e) {
        return e.channel() == Channel.NAO_CAMERA && e.kind().equals("frame") && e.error() == null;
    }

    @Test
    void theNaosCameraAndCallsReachFoxgloveAndAnotherTouchline() throws Exception {
        Requirement.robotSide("touchline-nao-sim");
        List<Envelope> here = new CopyOnWriteArrayList<>();
        List<Envelope> there = new CopyOnWriteArrayList<>();
        try (ServedField field = new ServedField();
             AutoCloseable heard = field.console().field().bus().subscribe(here::add);
             Console second = viewer();
             AutoCloseable seen = second.field().bus().subscribe(there::add);
             FoxgloveTestClient foxglove = new FoxgloveTestClient(field.server().port());
             Nao nao = nao(field.console())) {
            second.remote().view(new URI(field.server().url("127.0.0.1")), null);
            Await.until("frames in the first console", () -> here.stream().filter(NaoOnTheViewerIntegrationTest::naoFrame).count() >= 3);

            JSONObject image = foxglove.awaitChannel("/nao/camera/image");
            assertEquals("foxglove.CompressedImage", image.getString("schemaName"));
            foxglove.subscribe(1, image.getInt("id"));
            Await.until("a CompressedImage", () -> !foxglove.dataOf(1).isEmpty());
            DynamicMessage jpeg = FoxgloveTestClient.decode(image, foxglove.dataOf(1).get(0).payload());
            assertEquals("jpeg", jpeg.getField(jpeg.getDescriptorForType().findFieldByName("format")));
            ByteString data = (ByteString) jpeg.getField(jpeg.getDescriptorForType().findFieldByName("data"));
            assertEquals(0xFF, data.byteAt(0) & 0xFF);
            assertEquals(0xD8, data.byteAt(1) & 0xFF);
            assertTrue(data.size() > 1000, "a whole frame: " + data.size() + " bytes");

            Await.until("frames in the viewing console", () -> there.stream().anyMatch(NaoOnTheViewerIntegrationTest::naoFrame));
            Envelope remote = there.stream().filter(NaoOnTheViewerIntegrationTest::naoFrame).findFirst().orElseThrow();
            assertEquals(Origin.REMOTE, remote.origin());
            assertNotNull(remote.message(), "rebuilt with the advertised schema");
            List<byte[]> framesHere = new ArrayList<>();
            here.stream().filter(NaoOnTheViewerIntegrationTest::naoFrame).forEach(e -> framesHere.add(e.raw()));
            assertTrue(framesHere.stream().anyMatch(b -> Arrays.equals(b, remote.raw())),
                    "the viewer's frame is one the first console got, byte for byte");

            Await.until("the NAO link online", () -> nao.link().state() == touchline.transport.nao.ConnectionState.ONLINE);
            CallOutcome volume = nao.link().call("ALTextToSpeech", "getVolume").get(20, TimeUnit.SECONDS);
            assertInstanceOf(CallOutcome.Value.class, volume);
            // a call's channels are made by its first envelopes, so the viewer subscribes only after
            // them: call again until one call and its reply reach the viewing console
            Await.until("a call and its reply in the viewing console", () -> {
                boolean arrived = there.stream().anyMatch(e -> e.channel() == Channel.NAO_RPC
                        && e.direction() == touchline.transport.Direction.OUT)
                        && there.stream().anyMatch(e -> e.channel() == Channel.NAO_RPC
                        && e.direction() == touchline.transport.Direction.IN);
                if (!arrived) {
                    try {
                        nao.link().call("ALTextToSpeech", "getVolume").get(20, TimeUnit.SECONDS);
                    } catch (Exception e) {
                        throw new AssertionError(e);
                    }
                }
                return arrived;
            });
            Envelope reply = there.stream().filter(e -> e.channel() == Channel.NAO_RPC
                    && e.direction() == touchline.transport.Direction.IN).findFirst().orElseThrow();
            assertEquals(Origin.REMOTE, reply.origin());
            assertTrue(here.stream().anyMatch(e -> e.channel() == Channel.NAO_RPC && e.kind().equals(reply.kind())
                    && Arrays.equals(e.raw(), reply.raw())), "the same reply, byte for byte");
            assertEquals(0, second.remote().stream().orElseThrow().status().unusable(), second.remote().stream().orElseThrow().status().problem());
        }
    }

    /**
     * The NAO view's model on the viewing Touchline draws the first one's NAO: its newest frame
     * is one the first console's stream carried, byte for byte, though the viewer opened no
     * camera; and the viewer's commands to the NAO are refused with the remote view's words.
     */
    @Test
    void theViewersNaoViewShowsTheFirstConsolesCameraFrames() throws Exception {
        Requirement.robotSide("touchline-nao-sim");
        List<Envelope> here = new CopyOnWriteArrayList<>();
        try (NaoViews views = NaoViews.open(); AutoCloseable heard = views.field().console().field().bus().subscribe(here::add)) {
            int[] ports = views.ports();
            touchline.app.NaoViewModel first = views.first();
            touchline.app.NaoViewModel viewing = views.viewing();
            Console second = views.second();
            first.setResolution(1);
            first.showCamera(true);
            assertTrue(first.connect("127.0.0.1", Integer.toString(ports[0]), Integer.toString(ports[1]), "", true),
                    first.result());
            Await.until("a frame in the first console's NAO view", () -> first.frame().isPresent());
            Await.until("a frame in the viewer's NAO view", () -> viewing.frame().isPresent());
            assertTrue(second.naos().sessions().isEmpty(), "the viewer opened no NAO and no camera");

            byte[] shown = viewing.frame().orElseThrow().jpeg();
            assertEquals(0xFF, shown[0] & 0xFF);
            assertEquals(0xD8, shown[1] & 0xFF);
            assertEquals(320, viewing.frame().orElseThrow().width());
            List<byte[]> seenHere = new ArrayList<>();
            for (Envelope e : here) {
                if (naoFrame(e)) {
                    seenHere.add(touchline.proto.Nao.CamResponse.parseFrom(e.raw()).getImageData().toByteArray());
                }
            }
            assertTrue(seenHere.stream().anyMatch(b -> Arrays.equals(b, shown)),
                    "the viewer draws a frame the first console got, byte for byte");

            viewing.stand();
            assertEquals(Console.COMMANDS_OFF, viewing.result());
            assertFalse(viewing.connect("127.0.0.1", Integer.toString(ports[0]), "0", "", true));
            assertEquals(Console.COMMANDS_OFF, viewing.result());
        }
    }

    /**
     * The NAO view's result line on the viewing Touchline says the first one's NAO calls and
     * their outcomes (a value, the robot's error), taken from the call and reply envelopes the
     * viewer gets, as the first console's own line says them.
     */
    @Test
    void theViewersNaoViewSaysTheFirstConsolesCallsAndTheirOutcomes() throws Exception {
        Requirement.robotSide("touchline-nao-sim");
        try (NaoViews views = NaoViews.open()) {
            int[] ports = views.ports();
            touchline.app.NaoViewModel first = views.first();
            touchline.app.NaoViewModel viewing = views.viewing();
            assertTrue(first.connect("127.0.0.1", Integer.toString(ports[0]), "0", "", true), first.result());
            Await.until("the NAO online", () -> first.state().startsWith("online"));

            String volume = outcomeOnTheViewer(first, viewing, "getVolume");
            assertFalse(volume.contains("error"), volume);
            assertEquals(first.result(), volume, "the viewer says what the first console says");

            String refused = outcomeOnTheViewer(first, viewing, "noSuchMethod");
            assertTrue(refused.startsWith("ALTextToSpeech.noSuchMethod: error: "), refused);
            assertEquals(first.result(), refused);
        }
    }

    /**
     * Calls {@code ALTextToSpeech.method} on the first console until the viewer's NAO view says
     * its outcome: a call's channels are made by its first envelopes, so the viewer subscribes
     * only after them. Returns the viewer's line once the first console's says the same.
     */
    private static String outcomeOnTheViewer(touchline.app.NaoViewModel first, touchline.app.NaoViewModel viewing,
                                             String method) throws InterruptedException {
        String call = "ALTextToSpeech." + method + ": ";
        int[] polls = {0};
        Await.until(call + "outcome on the viewer", () -> {
            String line = viewing.result();
            if (line.startsWith(call) && !line.endsWith(touchline.app.NaoCallFeed.NO_REPLY_YET)) {
                return true;
            }
            if (polls[0]++ % 20 == 0) { // a call every ~200 ms
                first.call("ALTextToSpeech", method, "");
            }
            return false;
        });
        Await.until(call + "outcome on the first console",
                () -> first.result().equals(viewing.result()));
        return viewing.result();
    }
}
