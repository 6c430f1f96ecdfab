package touchline.protocol.ros2;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.*;

/** ROS 2 images to pixels: each encoding's bytes land as the RGB (or grey) values they mean. */
class RosImageTest {

    private static RosMessage image(String encoding, int w, int h, int step, byte[] data) {
        return new RosMessage("sensor_msgs/msg/Image", null,
                new String[] {"height", "width", "encoding", "is_bigendian", "step", "data"},
                new Object[] {h, w, encoding, 0, (long) step, data});
    }

    private static byte[] bytes(int... v) {
        byte[] b = new byte[v.length];
        for (int i = 0; i < v.length; i++) {
            b[i] = (byte) v[i];
        }
        return b;
    }

    private static RosImage.Pixels pixels(RosMessage m) {
        RosImage.Frame f = new RosImage().frame(m);
        return assertInstanceOf(RosImage.Pixels.class, f, f.toString());
    }

    @Test
    void rgb8KeepsItsOrderAndDropsRowPadding() {
        // 2×2, step 8: two padding bytes after each row
        RosImage.Pixels p = pixels(image("rgb8", 2, 2, 8, bytes(255, 0, 0, 0, 255, 0, 9, 9, 0, 0, 255, 10, 20, 30, 9, 9)));
        assertEquals(2, p.width());
        assertFalse(p.grey());
        assertArrayEquals(bytes(255, 0, 0, 0, 255, 0, 0, 0, 255, 10, 20, 30), p.data());
    }

    @Test
    void bgr8IsSwappedToRgb() {
        RosImage.Pixels p = pixels(image("bgr8", 2, 1, 6, bytes(255, 0, 0, 10, 20, 30)));
        assertArrayEquals(bytes(0, 0, 255, 30, 20, 10), p.data());
    }

    @Test
    void mono8IsGrey() {
        RosImage.Pixels p = pixels(image("mono8", 3, 2, 4, bytes(0, 128, 255, 7, 1, 2, 3, 7)));
        assertTrue(p.grey());
        assertArrayEquals(bytes(0, 128, 255, 1, 2, 3), p.data());
    }

    @Test
    void yuv422IsUyvyAndYuyvIsYuyvByBt601() {
        // U=128, V=128: grey at Y; then pure red's YUV (Y=76, U=85, V=255) → about (255, 0, 0)
        byte[] uyvy = bytes(128, 16, 128, 235, 85, 76, 255, 76);
        RosImage.Pixels p = pixels(image("yuv422", 4, 1, 8, uyvy));
        assertArrayEquals(bytes(16, 16, 16, 235, 235, 235, 254, 0, 0, 254, 0, 0), p.data());
        byte[] yuyv = bytes(16, 128, 235, 128, 76, 85, 76, 255);
        assertArrayEquals(p.data(), pixels(image("yuyv", 4, 1, 8, yuyv)).data());
        assertArrayEquals(p.data(), pixels(image("yuv422_yuy2", 4, 1, 8, yuyv)).data());
    }

    @Test
    void compressedImagesStayCompressedByFormatOrMagic() {
        byte[] jpeg = bytes(0xFF, 0xD8, 0xFF, 0xE0);
        byte[] png = bytes(0x89, 'P', 'N', 'G');
        RosImage images = new RosImage();
        assertEquals(new RosImage.Compressed(false, jpeg).png(), ((RosImage.Compressed) images.frame(compressed("jpeg", jpeg))).png());
        assertTrue(((RosImage.Compressed) images.frame(compressed("rgb8; png compressed bgr8", png))).png());
        assertFalse(((RosImage.Compressed) images.frame(compressed("", jpeg))).png());
        assertInstanceOf(RosImage.Refused.class, images.frame(compressed("tiff", bytes(1, 2, 3))));
    }

    private static RosMessage compressed(String format, byte[] data) {
        return new RosMessage("sensor_msgs/msg/CompressedImage", null, new String[] {"format", "data"},
                new Object[] {format, data});
    }

    @Test
    void anImageItCannotShowIsRefusedWithTheReason() {
        RosImage images = new RosImage();
        assertTrue(((RosImage.Refused) images.frame(image("bayer_rggb8", 2, 2, 2, new byte[4]))).reason().contains("bayer_rggb8"));
        assertTrue(((RosImage.Refused) images.frame(image("rgb8", 4, 4, 12, new byte[40]))).reason().contains("needs 48 bytes"));
        assertTrue(((RosImage.Refused) images.frame(image("rgb8", 0, 4, 0, new byte[0]))).reason().contains("bad size"));
        assertTrue(((RosImage.Refused) images.frame(image("rgb8", 4, 1, 6, new byte[12]))).reason().contains("step 6"));
        assertInstanceOf(RosImage.Refused.class, images.frame(image("yuv422", 3, 1, 6, new byte[6])));
    }
}
