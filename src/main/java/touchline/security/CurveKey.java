package touchline.security;

import zmq.util.Z85;

/**
 * One CURVE key (a 32-byte Curve25519 key) with its Z85 text, the form libzmq and JeroMQ take
 * and the key files hold ({@link KeyFile#curveKey}). Equal keys compare equal; {@link #toString()} never shows the key.
 */
public final class CurveKey {

    public static final int BYTES = 32;
    public static final int Z85_CHARS = 40;
    private static final String Z85_ALPHABET =
            "0123456789abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ.-:+=^!/*?&<>()[]{}@%$#";

    private final String z85;

    private CurveKey(String z85) {
        this.z85 = z85;
    }

    /**
     * Checks and wraps a Z85 key.
     *
     * @param where what to name in the error, e.g. "keys/console.secret: secret-key"
     */
    public static CurveKey parse(String z85, String where) throws KeyException {
        if (z85.length() != Z85_CHARS) {
            throw new KeyException(where + " has " + z85.length() + " characters; a CURVE key has " + Z85_CHARS
                    + " (Z85 of 32 bytes); " + KeyFile.RECOVER);
        }
        for (int i = 0; i < z85.length(); i++) {
            if (Z85_ALPHABET.indexOf(z85.charAt(i)) < 0) {
                throw new KeyException(where + ": character " + (i + 1) + " ('" + z85.charAt(i)
                        + "') is not Z85, corrupted; " + KeyFile.RECOVER);
            }
        }
        byte[] bytes = Z85.decode(z85);
        if (bytes == null || bytes.length != BYTES) {
            throw new KeyException(where + ": not a Z85-encoded 32-byte key, corrupted; " + KeyFile.RECOVER);
        }
        return new CurveKey(z85);
    }

    public String z85() {
        return z85;
    }

    public byte[] bytes() {
        return Z85.decode(z85);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof CurveKey k && k.z85.equals(z85);
    }

    @Override
    public int hashCode() {
        return z85.hashCode();
    }

    @Override
    public String toString() {
        return "CurveKey[not shown]";
    }
}
