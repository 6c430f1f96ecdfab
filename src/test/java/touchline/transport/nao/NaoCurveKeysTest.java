package touchline.transport.nao;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.charset.StandardCharsets;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermission;
import java.util.Map;
import java.util.Set;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The key-file reader's good path and every error it must explain (missing, corrupted, wrong length). */
class NaoCurveKeysTest {

    @TempDir
    Path dir;

    @Test
    void writtenKeysReadBackAsValidCurveKeys() throws Exception {
        new CurveKeyFiles().write(dir, false);
        NaoClientKeys keys = NaoClientKeys.load(dir);
        assertEquals(32, keys.clientSecret().bytes().length);
        assertNotEquals(keys.clientPublic(), keys.clientSecret());
        assertEquals(keys.serverPublic(), KeyFileText.read(dir.resolve("nao-server.secret")).curveKey("public-key"));
        assertNotEquals(keys.serverPublic(), keys.clientPublic());
        assertEquals(Set.of(PosixFilePermission.OWNER_READ, PosixFilePermission.OWNER_WRITE),
                Files.getPosixFilePermissions(dir.resolve("console.secret")));
        assertEquals(Set.of(PosixFilePermission.OWNER_READ, PosixFilePermission.OWNER_WRITE,
                PosixFilePermission.OWNER_EXECUTE), Files.getPosixFilePermissions(dir));
        assertTrue(Files.readString(dir.resolve("console.public")).startsWith("# "), "says what the file is");
        assertTrue(!keys.clientSecret().toString().contains(keys.clientSecret().z85()), "never printed");
    }

    @Test
    void refusesToOverwriteWithoutForce() throws Exception {
        new CurveKeyFiles().write(dir, false);
        String before = Files.readString(dir.resolve("console.secret"));
        assertThrows(FileAlreadyExistsException.class, () -> new CurveKeyFiles().write(dir, false));
        assertEquals(before, Files.readString(dir.resolve("console.secret")));
        new CurveKeyFiles().write(dir, true);
        assertNotEquals(before, Files.readString(dir.resolve("console.secret")));
    }

    @Test
    void missingFileSaysWhichAndHowToRecover() throws Exception {
        new CurveKeyFiles().write(dir, false);
        Files.delete(dir.resolve("nao-server.public"));
        KeyFileException e = assertThrows(KeyFileException.class, () -> NaoClientKeys.load(dir));
        assertTrue(e.getMessage().contains("nao-server.public: missing"), e.getMessage());
        assertTrue(e.getMessage().contains("touchline keys new"), e.getMessage());
    }

    @Test
    void corruptedZ85IsNamed() throws Exception {
        new CurveKeyFiles().write(dir, false);
        Path f = dir.resolve("console.secret");
        String text = Files.readString(f);
        String secret = text.substring(text.indexOf("secret-key = ") + 13, text.indexOf("secret-key = ") + 53);
        Files.writeString(f, text.replace(secret, "\"" + secret.substring(1)));
        KeyFileException e = assertThrows(KeyFileException.class, () -> NaoClientKeys.load(dir));
        assertTrue(e.getMessage().contains("console.secret: secret-key: character 1 ('\"') is not Z85"),
                e.getMessage());
    }

    @Test
    void wrongLengthIsNamed() throws Exception {
        new CurveKeyFiles().write(dir, false);
        Path f = dir.resolve("nao-server.public");
        String text = Files.readString(f);
        Files.writeString(f, text.replaceAll("(public-key = \\S{30})\\S+", "$1"));
        KeyFileException e = assertThrows(KeyFileException.class, () -> NaoClientKeys.load(dir));
        assertTrue(e.getMessage().contains("public-key has 30 characters; a CURVE key has 40"), e.getMessage());
    }

    @Test
    void garbageLinesAndBinaryAreCorrupted() throws Exception {
        Path f = dir.resolve("console.secret");
        Files.writeString(f, "# comment\n\npublic-key\n");
        KeyFileException e = assertThrows(KeyFileException.class, () -> KeyFileText.read(f));
        assertTrue(e.getMessage().contains("line 3: not 'name = value'"), e.getMessage());
        Files.write(f, new byte[] {(byte) 0xff, (byte) 0xfe, 0, 1});
        e = assertThrows(KeyFileException.class, () -> KeyFileText.read(f));
        assertTrue(e.getMessage().contains("not UTF-8"), e.getMessage());
        Files.writeString(f, "# only a comment\n", StandardCharsets.UTF_8);
        e = assertThrows(KeyFileException.class, () -> KeyFileText.read(f).curveKey("secret-key"));
        assertTrue(e.getMessage().contains("no 'secret-key = ...' line"), e.getMessage());
    }

    @Test
    void keyDirectoryFollowsOptionThenEnvironmentThenXdg() {
        assertEquals(Path.of("/k"), KeyDirectory.resolve("/k", Map.of("TOUCHLINE_KEYS", "/e"), "/home/u"));
        assertEquals(Path.of("/e"), KeyDirectory.resolve(null, Map.of("TOUCHLINE_KEYS", "/e"), "/home/u"));
        assertEquals(Path.of("/x/touchline/keys"), KeyDirectory.resolve(null, Map.of("XDG_CONFIG_HOME", "/x"), "/home/u"));
        assertEquals(Path.of("/home/u/.config/touchline/keys"), KeyDirectory.resolve(null, Map.of(), "/home/u"));
    }
}
