package touchline.protocol;

import com.google.protobuf.CodedInputStream;
import com.google.protobuf.InvalidProtocolBufferException;
import com.google.protobuf.WireFormat;
import touchline.proto.Fumanoid;


/**
 * Decodes FUmanoids {@code Message} payloads with the extension registry and builds the
 * console's own messages. Pure: no I/O, no threads.
 */
public final class MessageCodec {

    /** The robot ID the console uses in its own messages. */
    public static final int CONSOLE_ID = 0;

    private final MessageKinds kinds;

    public MessageCodec(MessageKinds kinds) {
        this.kinds = kinds;
    }

    public MessageKinds kinds() {
        return kinds;
    }

    public MessageResult decode(byte[] payload) {
        Fumanoid.Message message;
        try {
            message = Fumanoid.Message.parseFrom(payload, kinds.registry());
        } catch (InvalidProtocolBufferException e) {
            String reason = e.getMessage() == null ? "not a protobuf message" : e.getMessage();
            if (reason.contains("required fields")) {
                reason = "message without the required robotID";
            }
            return new MessageResult.Malformed("protobuf: " + firstLine(reason));
        } catch (RuntimeException e) {
            return new MessageResult.Malformed("protobuf: " + e.getClass().getSimpleName());
        }
        int extension = firstExtension(payload);
        String kind = extension == 0 ? "empty" : kinds.kindOf(extension);
        return new MessageResult.Decoded(message, extension, kind);
    }

    /** No robot ID could be read: {@link #robotIdOf} on a payload that {@link #decode} calls malformed. */
    public static final int NO_ROBOT_ID = Integer.MIN_VALUE;

    /**
     * The robotID a payload carries, read from the bytes without building the message (field 1
     * as a varint, the last one winning as in the parse), or {@link #NO_ROBOT_ID}. Lets the
     * transport check the tag (which covers the robot ID) of a datagram the full decode refused.
     */
    public static int robotIdOf(byte[] payload) {
        int robotId = NO_ROBOT_ID;
        try {
            CodedInputStream in = CodedInputStream.newInstance(payload);
            while (!in.isAtEnd()) {
                int tag = in.readTag();
                if (WireFormat.getTagFieldNumber(tag) == 1 && WireFormat.getTagWireType(tag) == WireFormat.WIRETYPE_VARINT) {
                    robotId = in.readInt32();
                } else if (!in.skipField(tag)) {
                    return NO_ROBOT_ID; // an end-group tag at the top level: not a message
                }
            }
        } catch (java.io.IOException e) {
            return NO_ROBOT_ID;
        }
        return robotId;
    }

    /**
     * The number of the first field after robotID: the extension the message carries. Read from
     * the bytes because asking the parsed message for all its fields costs more than the parse.
     */
    static int firstExtension(byte[] payload) {
        try {
            CodedInputStream in = CodedInputStream.newInstance(payload);
            while (!in.isAtEnd()) {
                int tag = in.readTag();
                int field = WireFormat.getTagFieldNumber(tag);
                if (field != 1) {
                    return field;
                }
                in.skipField(tag);
            }
        } catch (java.io.IOException e) {
            return 0; // cannot happen for bytes that parsed; treated as "no extension"
        }
        return 0;
    }

    private static String firstLine(String s) {
        int nl = s.indexOf('\n');
        String line = nl < 0 ? s : s.substring(0, nl);
        return line.length() > 160 ? line.substring(0, 160) + "…" : line;
    }

    public Fumanoid.Message optionListRequest() {
        return Fumanoid.Message.newBuilder().setRobotID(CONSOLE_ID)
                .setExtension(Fumanoid.debugOptionListRequest, Fumanoid.DebugOptionListRequest.getDefaultInstance())
                .build();
    }

    /** Switches an option and sets its place in the match digest (1 = first, 0 = out of it). */
    public Fumanoid.Message optionRequest(String name, boolean enable, int matchRank) {
        return Fumanoid.Message.newBuilder().setRobotID(CONSOLE_ID)
                .setExtension(Fumanoid.debugOptionRequest, Fumanoid.DebugOptionRequest.newBuilder().setName(name)
                        .setEnable(enable).setMatchRank(matchRank).build())
                .build();
    }

    public Fumanoid.Message optionRequest(String name, boolean enable) {
        return Fumanoid.Message.newBuilder().setRobotID(CONSOLE_ID)
                .setExtension(Fumanoid.debugOptionRequest,
                        Fumanoid.DebugOptionRequest.newBuilder().setName(name).setEnable(enable).build())
                .build();
    }
}
