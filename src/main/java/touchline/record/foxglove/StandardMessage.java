package touchline.record.foxglove;

import com.google.protobuf.Message;

/**
 * One message in a Foxglove standard schema ({@code foxglove.Log}, {@code foxglove.CompressedImage}, ...)
 * made from a Touchline envelope: the topic it goes out on, its log time and the message, whose
 * type's full name is the schema name the viewers recognise.
 */
public record StandardMessage(String topic, long logTimeNanos, Message message) {

    /** The schema name, e.g. {@code foxglove.Log}. */
    public String schemaName() {
        return message.getDescriptorForType().getFullName();
    }
}
