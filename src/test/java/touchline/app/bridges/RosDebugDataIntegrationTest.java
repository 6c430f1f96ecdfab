package touchline.app.bridges;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.app.Console;
import touchline.app.ConsoleConfig;
import touchline.model.store.LatestValues;
import touchline.proto.Fumanoid;
import touchline.testing.Await;
import touchline.testing.SimulatedRos2Robot;
import touchline.transport.UdpConfig;

import javax.imageio.ImageIO;
import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.util.Set;

import static org.junit.jupiter.api.Assertions.*;

/**
 * The simulated ROS 2 robot's camera, joints and diagnostics reach the views' model as a small
 * robot's image and tables would: kept as the newest value of its topic, and listed as a source
 * for the image and table views.
 */
@Tag("interop")
class RosDebugDataIntegrationTest {

    @Test
    void aCompressedImageJointsDiagnosticsAndMarkersFromTheSimulatedRobotReachTheViewModel() throws Exception {
        try (Console console = new Console(ConsoleConfig.defaults().withUdp(UdpConfig.defaults()
                .withBindAddress("127.0.0.1").withListenPort(0)).withGameControllerPort(0)).start();
             SimulatedRos2Robot robot = new SimulatedRos2Robot("booster-1")) {
            int id = console.bridges().connect(BridgeAddress.parse("booster-1=" + robot.url()), null);
            LatestValues latest = console.field().stores().latest();
            Await.until("the camera, joints and diagnostics kept", () -> latest.get(id, "/camera/image/compressed").isPresent()
                    && latest.get(id, "/joint_states").isPresent() && latest.get(id, "/diagnostics").isPresent());

            Fumanoid.DebugImage img = (Fumanoid.DebugImage) latest.get(id, "/camera/image/compressed").orElseThrow().data();
            assertEquals(Fumanoid.ImageFormat.JPEG_VALUE, img.getFormat());
            BufferedImage decoded = ImageIO.read(new ByteArrayInputStream(img.getData().toByteArray()));
            assertEquals(64, decoded.getWidth());
            assertEquals(48, decoded.getHeight());
            assertEquals(new LatestValues.Key(id, "/camera/image/compressed"),
                    latest.translatedSources(Set.of(Fumanoid.DebugKind.IMAGE_VALUE)).get(0), "the image view's source");

            Fumanoid.DebugTable joints = (Fumanoid.DebugTable) latest.get(id, "/joint_states").orElseThrow().data();
            assertEquals(24, joints.getRowsCount());
            assertEquals("head_yaw", joints.getRows(0).getCells(0));
            Fumanoid.DebugTable diagnostics = (Fumanoid.DebugTable) latest.get(id, "/diagnostics").orElseThrow().data();
            assertTrue(diagnostics.getRows(0).getCells(4).startsWith("Battery="), diagnostics.toString());
            assertEquals(2, latest.translatedSources(Set.of(Fumanoid.DebugKind.TABLE_VALUE)).size());

            Await.until("a temperature in the Robots table", () -> console.field().robots().robot(id)
                    .filter(r -> r.temperature() >= 40 && r.temperature() <= 43).isPresent());

            Await.until("the markers kept", () -> latest.get(id, "/markers").isPresent());
            touchline.proto.Drawing.FieldDrawing markers =
                    (touchline.proto.Drawing.FieldDrawing) latest.get(id, "/markers").orElseThrow().data();
            assertEquals(4, markers.getShapesCount(), "ball, path, kick range and text after the DELETEALL: " + markers);
        }
    }
}
