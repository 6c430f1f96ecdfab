package touchline.transport.nao;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.security.KeyDir;
import touchline.security.KeyException;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.SecureRandom;
import java.time.Instant;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The NAO link's client keys from a key directory made by {@code touchline keys new} ({@link KeyDir}):
 * the good path and every error they must explain (missing, corrupted, wrong length, too open).
 */
class NaoCurveKeysTest {

    @TempDir
    Path tmp;

    private KeyDir made() throws KeyException {
        KeyDir dir = new KeyDir(tmp.resolve("keys"));
        dir.create(false, new SecureRandom(), Instant.now());
        return dir;
    }

    @Test
    void keysNewGivesValidClientKeys() throws Exception {
        KeyDir dir = made();
        NaoClientKeys keys = NaoClientKeys.load(dir);
        assertEquals(32, keys.clientSecret().bytes().length);
        assertNotEquals(keys.clientPublic(), keys.clientSecret());
        assertEquals(keys.serverPublic(), dir.read(KeyDir.NAO_SERVER_SECRET, true).curveKey("public-key"));
        assertEquals(keys.clientPublic(), dir.read(KeyDir.CONSOLE_PUBLIC, false).curveKey("public-key"));
        assertNotEquals(keys.serverPublic(), keys.clientPublic());
        assertTrue(!keys.clientSecret().toString().contains(keys.clientSecret().z85()), "never printed");
    }

    @Test
    void missingFileSaysWhichAndHowToRecover() throws Exception {
        KeyDir dir = made();
        Files.delete(dir.file(KeyDir.NAO_SERVER_PUBLIC));
        KeyException e = assertThrows(KeyException.class, () -> NaoClientKeys.load(dir));
        assertTrue(e.getMessage().contains("nao-server.public: missing"), e.getMessage());
        assertTrue(e.getMessage().contains("touchline keys new"), e.getMessage());
    }

    @Test
    void corruptedZ85IsNamed() throws Exception {
        KeyDir dir = made();
        Path f = dir.file(KeyDir.CONSOLE_SECRET);
        String text = Files.readString(f);
        String secret = text.substring(text.indexOf("secret-key = ") + 13, text.indexOf("secret-key = ") + 53);
        Files.writeString(f, text.replace(secret, "\"" + secret.substring(1)));
        KeyException e = assertThrows(KeyException.class, () -> NaoClientKeys.load(dir));
        assertTrue(e.getMessage().contains("console.secret: secret-key: character 1 ('\"') is not Z85"),
                e.getMessage());
    }

    @Test
    void wrongLengthIsNamed() throws Exception {
        KeyDir dir = made();
        Path f = dir.file(KeyDir.NAO_SERVER_PUBLIC);
        String text = Files.readString(f);
        Files.writeString(f, text.replaceAll("(public-key = \\S{30})\\S+", "$1"));
        KeyException e = assertThrows(KeyException.class, () -> NaoClientKeys.load(dir));
        assertTrue(e.getMessage().contains("public-key has 30 characters; a CURVE key has 40"), e.getMessage());
    }

    @Test
    void garbageLinesBinaryAndMissingLinesAreCorrupted() throws Exception {
        KeyDir dir = made();
        Path f = dir.file(KeyDir.CONSOLE_SECRET);
        Files.writeString(f, "# comment\n\npublic-key\n");
        KeyException e = assertThrows(KeyException.class, () -> NaoClientKeys.load(dir));
        assertTrue(e.getMessage().contains("console.secret line 3: not 'name = value'"), e.getMessage());
        Files.write(f, new byte[] {(byte) 0xff, (byte) 0xfe, 0, 1});
        e = assertThrows(KeyException.class, () -> NaoClientKeys.load(dir));
        assertTrue(e.getMessage().contains("not UTF-8"), e.getMessage());
        Files.writeString(f, "# only a comment\npublic-key = " + "0".repeat(40) + "\n", StandardCharsets.UTF_8);
        e = assertThrows(KeyException.class, () -> NaoClientKeys.load(dir));
        assertTrue(e.getMessage().contains("no 'secret-key = ...' line"), e.getMessage());
    }

    @Test
    void aClientSecretOthersCanReadIsRefused() throws Exception {
        KeyDir dir = made();
        Path f = dir.file(KeyDir.CONSOLE_SECRET);
        Files.setPosixFilePermissions(f, PosixFilePermissions.fromString("rw-r--r--"));
        KeyException e = assertThrows(KeyException.class, () -> NaoClientKeys.load(dir));
        assertTrue(e.getMessage().contains("chmod 600 " + f), e.getMessage());
        Files.setPosixFilePermissions(f, PosixFilePermissions.fromString("rw-------"));
        assertEquals(32, NaoClientKeys.load(dir).clientSecret().bytes().length);
    }
}
