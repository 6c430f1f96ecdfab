package touchline.record;

import com.google.protobuf.Descriptors.FieldDescriptor;
import com.google.protobuf.Message;

/**
 * Where a channel's robot timestamp sits in the wire bytes: the field number of the
 * extension the channel's messages carry and of the {@code timestamp} field inside it. The
 * recorder reads the value straight from the payload bytes with a small wire-format walk:
 * asking the decoded message through protobuf reflection cost more per datagram than
 * writing the datagram to the file. The walk stops at the first timestamp, and gives up
 * (log time is used instead) once it passes the timestamp's field number: encoders write
 * fields in number order, so this reads only the first few bytes of a message. A message
 * that repeats the field (legal protobuf, never written by our encoders) gets its first value.
 */
final class RobotTimestamp {

    private static final int VARINT = 0;
    private static final int FIXED64 = 1;
    private static final int LENGTH_DELIMITED = 2;
    private static final int FIXED32 = 5;

    private final int extensionNumber;
    private final int timestampNumber;
    private final boolean zigZag;
    private final boolean fixed;

    RobotTimestamp(int extensionNumber, FieldDescriptor timestamp) {
        this.extensionNumber = extensionNumber;
        this.timestampNumber = timestamp.getNumber();
        this.zigZag = timestamp.getType() == FieldDescriptor.Type.SINT64;
        this.fixed = timestamp.getType() == FieldDescriptor.Type.FIXED64
                || timestamp.getType() == FieldDescriptor.Type.SFIXED64;
    }

    /** The timestamp location for messages like {@code sample}, or null when its extension has none. */
    static RobotTimestamp of(Message sample) {
        for (FieldDescriptor f : sample.getAllFields().keySet()) {
            if (f.isExtension() && f.getJavaType() == FieldDescriptor.JavaType.MESSAGE && !f.isRepeated()) {
                FieldDescriptor ts = f.getMessageType().findFieldByName("timestamp");
                if (ts != null && ts.getJavaType() == FieldDescriptor.JavaType.LONG && !ts.isRepeated()) {
                    return new RobotTimestamp(f.getNumber(), ts);
                }
                return null;
            }
        }
        return null;
    }

    /** The robot's timestamp (ms) converted to ns, or {@code fallback} when the bytes hold none. */
    long nanos(byte[] b, int off, int len, long fallback) {
        int end = off + len;
        int at = off;
        while (at < end) {
            long tag = varint(b, at, end);
            if (tag < 0) {
                return fallback;
            }
            at = next;
            int field = (int) (tag >>> 3);
            int wire = (int) (tag & 7);
            if (field == extensionNumber && wire == LENGTH_DELIMITED) {
                long n = varint(b, at, end);
                if (n < 0 || n > end - next) {
                    return fallback;
                }
                int start = next;
                long inner = timestampIn(b, start, (int) (start + n));
                return inner == Long.MIN_VALUE ? fallback : inner * 1_000_000L;
            } else {
                at = skip(b, at, end, wire);
                if (at < 0) {
                    return fallback;
                }
            }
        }
        return fallback;
    }

    private long timestampIn(byte[] b, int at, int end) {
        while (at < end) {
            long tag = varint(b, at, end);
            if (tag < 0) {
                return Long.MIN_VALUE;
            }
            at = next;
            int wire = (int) (tag & 7);
            int field = (int) (tag >>> 3);
            if (field == timestampNumber) {
                if (fixed && wire == FIXED64 && at + 8 <= end) {
                    return fixed64(b, at);
                }
                if (!fixed && wire == VARINT) {
                    long v = varintValue(b, at, end);
                    return next < 0 ? Long.MIN_VALUE : zigZag ? (v >>> 1) ^ -(v & 1) : v;
                }
                return Long.MIN_VALUE;
            }
            if (field > timestampNumber) {
                return Long.MIN_VALUE;
            }
            at = skip(b, at, end, wire);
            if (at < 0) {
                return Long.MIN_VALUE;
            }
        }
        return Long.MIN_VALUE;
    }

    // The walk's cursor after the last varint read; one walker per writer thread, so a field is fine.
    private int next;

    /** A non-negative varint (tags, lengths); -1 when malformed. Sets {@link #next}. */
    private long varint(byte[] b, int at, int end) {
        long v = varintValue(b, at, end);
        return next < 0 || v < 0 ? -1 : v;
    }

    /** Any 64-bit varint; sets {@link #next} to -1 when malformed. */
    private long varintValue(byte[] b, int at, int end) {
        long v = 0;
        for (int shift = 0; shift < 64 && at < end; shift += 7) {
            byte x = b[at++];
            v |= (long) (x & 0x7F) << shift;
            if (x >= 0) {
                next = at;
                return v;
            }
        }
        next = -1;
        return 0;
    }

    private int skip(byte[] b, int at, int end, int wire) {
        switch (wire) {
            case VARINT -> {
                varintValue(b, at, end);
                return next;
            }
            case FIXED64 -> {
                return at + 8 <= end ? at + 8 : -1;
            }
            case LENGTH_DELIMITED -> {
                long n = varint(b, at, end);
                // compared as "n > room": next + n overflows for a length near 2^63, and the walk
                // went back to the start of the bytes and round forever
                return n < 0 || n > end - next ? -1 : (int) (next + n);
            }
            case FIXED32 -> {
                return at + 4 <= end ? at + 4 : -1;
            }
            default -> {
                return -1; // groups are not used by our protocol; give up and fall back to log time
            }
        }
    }

    private static long fixed64(byte[] b, int at) {
        long v = 0;
        for (int i = 7; i >= 0; i--) {
            v = (v << 8) | (b[at + i] & 0xFF);
        }
        return v;
    }
}
