package touchline.record;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The length-prefixed fields of an MCAP record as the reader takes them apart: a length that
 * runs past the record is an {@link IllegalArgumentException}, never an allocation.
 */
final class RecordFields {

    private RecordFields() {
    }

    static String string(ByteBuffer r) {
        return new String(bytes(r, r.getInt()), StandardCharsets.UTF_8);
    }

    static byte[] bytes(ByteBuffer r, long n) {
        if (n < 0 || n > r.remaining()) {
            throw new IllegalArgumentException("length " + n + " exceeds the record");
        }
        byte[] b = new byte[(int) n];
        r.get(b);
        return b;
    }

    static Map<String, String> map(ByteBuffer r) {
        int n = r.getInt();
        if (n < 0 || n > r.remaining()) {
            throw new IllegalArgumentException("map length " + n + " exceeds the record");
        }
        ByteBuffer m = r.slice(r.position(), n).order(ByteOrder.LITTLE_ENDIAN);
        r.position(r.position() + n);
        Map<String, String> out = new LinkedHashMap<>();
        while (m.hasRemaining()) {
            out.put(string(m), string(m));
        }
        return Collections.unmodifiableMap(out);
    }
}
