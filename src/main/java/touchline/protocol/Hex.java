package touchline.protocol;

/** Hex dumps of raw datagrams for the network console and error messages. */
public final class Hex {

    private static final char[] DIGITS = "0123456789abcdef".toCharArray();

    public String dump(byte[] bytes, int max) {
        int n = Math.min(bytes.length, max);
        StringBuilder out = new StringBuilder(n * 3);
        for (int i = 0; i < n; i++) {
            if (i > 0) {
                out.append(i % 16 == 0 ? '\n' : ' ');
            }
            out.append(DIGITS[(bytes[i] >> 4) & 0xF]).append(DIGITS[bytes[i] & 0xF]);
        }
        if (bytes.length > n) {
            out.append(" …");
        }
        return out.toString();
    }
}
