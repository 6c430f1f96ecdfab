package touchline.fuzz;

import touchline.protocol.nao.JpegHeader;

import javax.imageio.ImageIO;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.List;

/** A camera frame's JPEG header: the size is read or the bytes refused, within 16-bit sizes. */
final class JpegHeaderTarget implements FuzzTarget {

    @Override
    public String name() {
        return "jpeg";
    }

    @Override
    public void accept(byte[] input) {
        int[] size = JpegHeader.size(input);
        if (size != null) {
            FuzzTarget.check(size.length == 2 && size[0] >= 0 && size[0] <= 0xFFFF && size[1] >= 0 && size[1] <= 0xFFFF,
                    "size out of range");
        }
    }

    /** Small real JPEGs, as a camera sends them. */
    @Override
    public List<byte[]> seeds() {
        return List.of(jpeg(16, 8), jpeg(3, 5));
    }

    private static byte[] jpeg(int width, int height) {
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        image.setRGB(1, 1, 0x00FF8800);
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try {
            ImageIO.write(image, "jpeg", out);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return out.toByteArray();
    }
}
