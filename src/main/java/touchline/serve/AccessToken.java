package touchline.serve;

import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.security.SecureRandom;
import java.util.Base64;

/**
 * The secret a viewer presents to watch. Compared in constant time over SHA-256 digests, so
 * neither the content nor the length of the token leaks through how long a refusal takes.
 */
public final class AccessToken {

    private final byte[] expectedDigest;

    public AccessToken(String token) {
        if (token == null || token.isEmpty()) {
            throw new IllegalArgumentException("an access token must not be empty");
        }
        this.expectedDigest = digest(token);
    }

    /** A fresh token: 24 random bytes from {@code random}, URL-safe Base64 (32 characters). */
    public static String generate(SecureRandom random) {
        byte[] bytes = new byte[24];
        random.nextBytes(bytes);
        return Base64.getUrlEncoder().withoutPadding().encodeToString(bytes);
    }

    /** True when {@code presented} is the token; null (no token given) never is. */
    public boolean admits(String presented) {
        return presented != null && MessageDigest.isEqual(expectedDigest, digest(presented));
    }

    private static byte[] digest(String s) {
        try {
            return MessageDigest.getInstance("SHA-256").digest(s.getBytes(StandardCharsets.UTF_8));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every JVM has SHA-256", e);
        }
    }
}
