package touchline.model;

import com.google.protobuf.ByteString;
import com.google.protobuf.Message;
import touchline.protocol.DebugData;

import java.util.concurrent.ConcurrentHashMap;

/**
 * The names robots send with every message (option names, plot series names), decoded from
 * UTF-8 once instead of once per message: looked up by the bytes as they came off the wire.
 * A freshly parsed message holds its strings as bytes, and decoding them (check, copy, a new
 * String, its hash on the next map lookup) was the largest single cost of the model per
 * envelope; a name found here costs a hash over a few bytes and returns the same String object
 * each time (its hash already computed). The String is exactly what the message's own getter
 * returns ({@link ByteString#toStringUtf8}). Bounded: when {@code capacity} distinct names are
 * held (a robot sending ever new names), the table starts afresh. Safe from any thread.
 */
public final class Utf8Names {

    public static final int DEFAULT_CAPACITY = 4_096;

    private final int capacity;
    private final ConcurrentHashMap<ByteString, String> names = new ConcurrentHashMap<>();

    public Utf8Names() {
        this(DEFAULT_CAPACITY);
    }

    public Utf8Names(int capacity) {
        if (capacity <= 0) {
            throw new IllegalArgumentException("capacity must be positive: " + capacity);
        }
        this.capacity = capacity;
    }

    /** The name these UTF-8 bytes spell (invalid sequences replaced, as protobuf's getters do). */
    public String of(ByteString utf8) {
        String name = names.get(utf8);
        if (name == null) {
            name = utf8.toStringUtf8();
            if (names.size() >= capacity) {
                names.clear();
            }
            names.put(utf8, name);
        }
        return name;
    }

    /** The {@code option} of a data message (our own types through this table), or null when it has none. */
    public String optionOf(Message data) {
        ByteString own = DebugData.ownOptionBytesOf(data);
        return own != null ? of(own) : DebugData.optionOf(data);
    }

    /** Names held now (at most the capacity). */
    public int size() {
        return names.size();
    }
}
