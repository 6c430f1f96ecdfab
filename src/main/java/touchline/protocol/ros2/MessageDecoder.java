package touchline.protocol.ros2;

/**
 * Decodes the messages of one channel. Pure and stateless after construction: one instance
 * may be used from several threads. Never throws on bad bytes; the result says why.
 */
public interface MessageDecoder {

    /** The type the channel's messages carry ({@code sensor_msgs/msg/Image}), or the schema's name. */
    String typeName();

    /** Decodes {@code length} bytes of {@code data} from {@code offset} (a frame's payload, without copying). */
    DecodeResult decode(byte[] data, int offset, int length);

    default DecodeResult decode(byte[] data) {
        return decode(data, 0, data.length);
    }
}
