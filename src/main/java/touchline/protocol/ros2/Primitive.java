package touchline.protocol.ros2;

/**
 * The primitive types of a ROS 2 message definition, with their CDR size in bytes (0 for the
 * two string types, whose size is their length). {@code byte} and {@code char} are the ROS 2
 * aliases of an unsigned octet; IDL's names ({@code octet}, {@code boolean}, {@code long long},
 * ...) map onto the same constants.
 */
public enum Primitive {
    BOOL("bool", 1), BYTE("byte", 1), CHAR("char", 1),
    INT8("int8", 1), UINT8("uint8", 1), INT16("int16", 2), UINT16("uint16", 2),
    INT32("int32", 4), UINT32("uint32", 4), INT64("int64", 8), UINT64("uint64", 8),
    FLOAT32("float32", 4), FLOAT64("float64", 8), STRING("string", 0), WSTRING("wstring", 0);

    private final String word;
    private final int size;

    Primitive(String word, int size) {
        this.word = word;
        this.size = size;
    }

    /** The name in a {@code .msg} file. */
    public String word() {
        return word;
    }

    /** Bytes on the wire (and the CDR alignment); 0 for strings. */
    public int size() {
        return size;
    }

    /** True for everything but the strings: a value that plots and exports as a number (a bool as 0/1). */
    public boolean numeric() {
        return size > 0;
    }

    /** The primitive a {@code .msg} type word names, or null when it names a message type. */
    public static Primitive ofWord(String word) {
        for (Primitive p : values()) {
            if (p.word.equals(word)) {
                return p;
            }
        }
        return null;
    }
}
