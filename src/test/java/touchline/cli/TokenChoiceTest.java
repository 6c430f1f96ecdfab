package touchline.cli;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.*;

/** Where {@code serve}'s token comes from: the option, a file only its owner may read, or the environment. */
class TokenChoiceTest {

    private static Path tokenFile(Path dir, String mode, String text) throws Exception {
        Path f = dir.resolve("serve.token");
        Files.writeString(f, text);
        Files.setPosixFilePermissions(f, PosixFilePermissions.fromString(mode));
        return f;
    }

    @Test
    void aTokenFileOthersMayReadIsRefusedWithWhatToDo(@TempDir Path dir) throws Exception {
        Path f = tokenFile(dir, "rw-r--r--", "s3cret\n");
        StartFailure e = assertThrows(StartFailure.class, () -> new TokenChoice(null, f, Map.of()).token());
        assertEquals(StartFailure.BAD_INPUT, e.exitCode());
        assertTrue(e.getMessage().contains("may be read or changed by others (mode rw-r--r--): `chmod 600 " + f + "`"),
                e.getMessage());
        Files.setPosixFilePermissions(f, PosixFilePermissions.fromString("rw--w----"));
        assertThrows(StartFailure.class, () -> new TokenChoice(null, f, Map.of()).token(), "writable by the group");
    }

    @Test
    void anOwnerOnlyFileGivesItsFirstLine(@TempDir Path dir) throws Exception {
        Path f = tokenFile(dir, "rw-------", "  s3cret  \nsecond line\n");
        assertEquals("s3cret", new TokenChoice(null, f, Map.of(TokenChoice.ENV, "other")).token(),
                "the file wins over the environment");
        Files.setPosixFilePermissions(f, PosixFilePermissions.fromString("r--------"));
        assertEquals("s3cret", new TokenChoice(null, f, Map.of()).token());
    }

    @Test
    void theEnvironmentGivesItWhenNoOptionDoesAndNothingIsNoToken(@TempDir Path dir) throws Exception {
        assertEquals("from-env", new TokenChoice(null, null, Map.of(TokenChoice.ENV, "from-env\n")).token());
        assertEquals("given", new TokenChoice("given", null, Map.of(TokenChoice.ENV, "from-env")).token());
        assertNull(new TokenChoice(null, null, Map.of()).token());
    }

    @Test
    void anEmptyMissingOrContradictoryTokenIsASentence(@TempDir Path dir) throws Exception {
        Path empty = tokenFile(dir, "rw-------", "\n");
        assertTrue(assertThrows(StartFailure.class, () -> new TokenChoice(null, empty, Map.of()).token())
                .getMessage().contains("gives an empty token"));
        assertTrue(assertThrows(StartFailure.class, () -> new TokenChoice(null, dir.resolve("nope"), Map.of()).token())
                .getMessage().contains("cannot read the token file"));
        assertTrue(assertThrows(StartFailure.class, () -> new TokenChoice("t", empty, Map.of()).token())
                .getMessage().contains("contradict"));
        assertTrue(assertThrows(StartFailure.class, () -> new TokenChoice(null, null, Map.of(TokenChoice.ENV, " ")).token())
                .getMessage().contains("$" + TokenChoice.ENV + " gives an empty token"));
    }
}
