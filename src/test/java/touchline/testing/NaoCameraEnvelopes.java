package touchline.testing;

import com.google.protobuf.ByteString;
import touchline.proto.Nao.CamResponse;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.Origin;

import javax.imageio.ImageIO;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.InetSocketAddress;

/** NAO camera frames as the Envelope stream carries them, for tests that need one without a camera. */
public final class NaoCameraEnvelopes {

    public static final InetSocketAddress CAMERA = InetSocketAddress.createUnresolved("10.0.0.7", 5556);

    private NaoCameraEnvelopes() {
    }

    /** A black JPEG of this size. */
    public static byte[] jpeg(int width, int height) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try {
            ImageIO.write(new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB), "jpg", out);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return out.toByteArray();
    }

    /** The camera's reply carrying {@code jpeg}, as a camera stream (or a remote Touchline) publishes it. */
    public static Envelope frame(byte[] jpeg, long timeMicros, Origin origin) {
        CamResponse r = CamResponse.newBuilder().setImageData(ByteString.copyFrom(jpeg)).build();
        return new Envelope(timeMicros, Direction.IN, Channel.NAO_CAMERA, CAMERA, Envelope.NO_ROBOT, "frame", r,
                r.toByteArray(), null, origin);
    }
}
