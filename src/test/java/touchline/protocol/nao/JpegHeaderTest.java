package touchline.protocol.nao;

import org.junit.jupiter.api.Test;

import javax.imageio.ImageIO;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.util.Arrays;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

class JpegHeaderTest {

    static byte[] jpeg(int w, int h) throws Exception {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ImageIO.write(new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB), "jpg", out);
        return out.toByteArray();
    }

    @Test
    void readsTheSizeFromTheStartOfFrame() throws Exception {
        assertArrayEquals(new int[] {640, 480}, JpegHeader.size(jpeg(640, 480)));
        assertArrayEquals(new int[] {160, 120}, JpegHeader.size(jpeg(160, 120)));
    }

    @Test
    void garbageAndTruncatedInputGiveNull() throws Exception {
        assertNull(JpegHeader.size(new byte[0]));
        assertNull(JpegHeader.size(new byte[] {1, 2, 3, 4, 5}));
        assertNull(JpegHeader.size(new byte[] {(byte) 0xFF, (byte) 0xD8, (byte) 0xFF, (byte) 0xE0, 0x7F, 0x7F}));
        byte[] real = jpeg(64, 48);
        assertNull(JpegHeader.size(Arrays.copyOf(real, 30)));
    }
}
