package touchline.security;

import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.security.SecureRandom;
import java.util.Arrays;
import java.util.HexFormat;

/**
 * A team's 32-byte secret for the small robots' message tags, and its key-id (the first 4
 * bytes of SHA-256 of the key): the id tells keys apart in messages and is not secret. The
 * secret never appears in {@link #toString()}.
 */
public final class TeamKey {

    public static final int SIZE = 32;
    public static final int ID_SIZE = 4;

    private final byte[] secret;
    private final byte[] id;

    public TeamKey(byte[] secret) {
        if (secret.length != SIZE) {
            throw new IllegalArgumentException("a team key has " + SIZE + " bytes, not " + secret.length);
        }
        this.secret = secret.clone();
        this.id = idOf(secret);
    }

    /** 32 bytes from the given source of randomness (a {@link SecureRandom} in the product). */
    public static TeamKey generate(SecureRandom random) {
        byte[] k = new byte[SIZE];
        random.nextBytes(k);
        return new TeamKey(k);
    }

    static byte[] idOf(byte[] secret) {
        try {
            return Arrays.copyOf(MessageDigest.getInstance("SHA-256").digest(secret), ID_SIZE);
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("the JDK has no SHA-256", e);
        }
    }

    byte[] secret() {
        return secret;
    }

    public byte[] id() {
        return id.clone();
    }

    /** The key-id as 8 lowercase hex digits, e.g. {@code 630dcd29}. */
    public String idHex() {
        return HexFormat.of().formatHex(id);
    }

    /** The secret as 64 lowercase hex digits: only for writing the key file and the robot's header. */
    public String secretHex() {
        return HexFormat.of().formatHex(secret);
    }

    boolean sameId(byte[] data, int offset) {
        return Arrays.equals(id, 0, ID_SIZE, data, offset, offset + ID_SIZE);
    }

    @Override
    public String toString() {
        return "team key " + idHex();
    }
}
