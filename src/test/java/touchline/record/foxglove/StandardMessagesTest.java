package touchline.record.foxglove;

import org.junit.jupiter.api.Test;
import touchline.proto.Fumanoid;
import touchline.proto.foxglove.CompressedImage;
import touchline.proto.foxglove.FrameTransforms;
import touchline.proto.foxglove.ImageAnnotations;
import touchline.proto.foxglove.Log;
import touchline.proto.foxglove.Point2;
import touchline.proto.foxglove.PointsAnnotation;
import touchline.proto.foxglove.RawImage;
import touchline.proto.foxglove.SceneUpdate;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;

import javax.imageio.ImageIO;
import java.io.ByteArrayInputStream;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

class StandardMessagesTest {

    private final StandardMessages convert = new StandardMessages();

    @Test
    void debugTextIsALogOnTheRobotsTopic() {
        List<StandardMessage> out = convert.convert(FoxgloveFixture.text(1_500_250, 3, "behaviour", "ball lost"));
        assertEquals(1, out.size());
        assertEquals("/robot/3/log", out.get(0).topic());
        assertEquals("foxglove.Log", out.get(0).schemaName());
        Log log = (Log) out.get(0).message();
        assertEquals("ball lost", log.getMessage());
        assertEquals("robot3/behaviour", log.getName());
        assertEquals(Log.Level.INFO, log.getLevel());
        assertEquals(1, log.getTimestamp().getSeconds());
        assertEquals(500_250_000, log.getTimestamp().getNanos());
        assertEquals(1_500_250_000L, out.get(0).logTimeNanos());
    }

    @Test
    void jpegImagesKeepTheirBytesAndRawFramesBecomeRawImages() throws Exception {
        byte[] jpeg = FoxgloveFixture.jpeg(40, 30);
        CompressedImage c = (CompressedImage) convert.convert(
                FoxgloveFixture.image(10, 2, Fumanoid.ImageFormat.JPEG, 40, 30, jpeg)).get(0).message();
        assertEquals("jpeg", c.getFormat());
        assertArrayEquals(jpeg, c.getData().toByteArray());
        assertEquals("robot2/demo.image", c.getFrameId());

        byte[] gray = new byte[40 * 30];
        gray[41] = 7;
        StandardMessage m = convert.convert(FoxgloveFixture.image(10, 2, Fumanoid.ImageFormat.GRAY8, 40, 30, gray)).get(0);
        assertEquals("/robot/2/camera", m.topic());
        RawImage r = (RawImage) m.message();
        assertEquals("mono8", r.getEncoding());
        assertEquals(40, r.getStep());
        assertArrayEquals(gray, r.getData().toByteArray());
    }

    @Test
    void imagesWithoutAStandardFormAreCountedNotGuessed() {
        assertEquals(List.of(), convert.convert(FoxgloveFixture.image(10, 2, Fumanoid.ImageFormat.GRAY8, 40, 30, new byte[7])));
        assertEquals(List.of(), convert.convert(
                FoxgloveFixture.image(10, 2, Fumanoid.ImageFormat.COLOR_CLASSES, 4, 1, new byte[4])));
        assertEquals(2, convert.skipped());
    }

    @Test
    void regionsAreClosedRectanglesOnAFrameOfTheirSize() throws Exception {
        List<StandardMessage> out = convert.convert(FoxgloveFixture.regions(2_000_000, 1, new int[]{1, 10, 20, 30, 45}));
        assertEquals(List.of("/robot/1/regions/frame", "/robot/1/regions"), out.stream().map(StandardMessage::topic).toList());
        CompressedImage frame = (CompressedImage) out.get(0).message();
        var png = ImageIO.read(new ByteArrayInputStream(frame.getData().toByteArray()));
        assertEquals(160, png.getWidth());
        assertEquals(120, png.getHeight());
        ImageAnnotations a = (ImageAnnotations) out.get(1).message();
        PointsAnnotation box = a.getPoints(0);
        assertEquals(PointsAnnotation.Type.LINE_LOOP, box.getType());
        assertEquals(List.of(p(10, 20), p(30, 20), p(30, 45), p(10, 45)), box.getPointsList());
        assertEquals(frame.getTimestamp(), box.getTimestamp()); // drawn on that frame
        assertEquals("ball", a.getTexts(0).getText());
        assertEquals(1.0, box.getOutlineColor().getR()); // the ball's orange
    }

    @Test
    void aPositionPlacesTheRobotOnTheFieldInMetres() {
        List<StandardMessage> out = convert.convert(FoxgloveFixture.status(5, 4, 1500, -250, (float) Math.PI / 2));
        FrameTransforms tf = (FrameTransforms) out.get(0).message();
        assertEquals("/tf", out.get(0).topic());
        assertEquals("field", tf.getTransforms(0).getParentFrameId());
        assertEquals("robot4", tf.getTransforms(0).getChildFrameId());
        assertEquals(1.5, tf.getTransforms(0).getTranslation().getX(), 1e-6);
        assertEquals(-0.25, tf.getTransforms(0).getTranslation().getY(), 1e-6);
        assertEquals(Math.sqrt(0.5), tf.getTransforms(0).getRotation().getZ(), 1e-6);
        SceneUpdate scene = (SceneUpdate) out.get(1).message();
        assertEquals("/field/scene", out.get(1).topic());
        assertEquals("robot4", scene.getEntities(0).getId());
        assertEquals(1.5, scene.getEntities(0).getCubes(0).getPose().getPosition().getX(), 1e-6);
        assertTrue(scene.getEntities(0).getTexts(0).getText().contains("striker"));
    }

    @Test
    void theNaoCameraIsACompressedImageLiveAndFromARecording() throws Exception {
        byte[] jpeg = FoxgloveFixture.jpeg(64, 48);
        Envelope live = FoxgloveFixture.naoFrame(9, jpeg);
        Envelope recorded = new Envelope(9, Direction.IN, Channel.NAO_CAMERA, null, Envelope.NO_ROBOT, "frame", null,
                live.raw(), null); // a recording gives the reply's bytes, not the message
        for (Envelope e : List.of(live, recorded)) {
            StandardMessage m = convert.convert(e).get(0);
            assertEquals("/nao/camera/image", m.topic());
            assertArrayEquals(jpeg, ((CompressedImage) m.message()).getData().toByteArray());
        }
    }

    @Test
    void whatTheConsoleSentAndMalformedDatagramsMapToNothing() {
        Envelope text = FoxgloveFixture.text(1, 3, "o", "t");
        Envelope out = new Envelope(1, Direction.OUT, Channel.FUMANOID, null, 3, "debugText", text.message(), text.raw(), null);
        Envelope bad = new Envelope(1, Direction.IN, Channel.FUMANOID, null, 3, "malformed", null, new byte[]{1}, "short");
        assertEquals(List.of(), convert.convert(out));
        assertEquals(List.of(), convert.convert(bad));
        assertEquals(0, convert.skipped());
    }

    private static Point2 p(double x, double y) {
        return Point2.newBuilder().setX(x).setY(y).build();
    }
}
