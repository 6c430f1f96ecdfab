package touchline.cli;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;
import touchline.security.KeyDir;
import touchline.security.TeamKey;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.Arrays;
import java.util.HexFormat;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.*;

class KeysCommandTest {

    @TempDir
    Path tmp;

    private final StringWriter out = new StringWriter();
    private final StringWriter err = new StringWriter();

    private int run(Map<String, String> env, String... args) {
        CommandLine cl = new CommandLine(new KeysCommand(env));
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(err, true));
        return cl.execute(args);
    }

    @Test
    void newThenShowThroughTheEnvironmentsKeyDirectory() throws Exception {
        Path dir = tmp.resolve("keys");
        Map<String, String> env = Map.of("TOUCHLINE_KEYS", dir.toString());
        assertEquals(0, run(env, "new"));
        TeamKey key = new KeyDir(dir).teamKey();
        assertTrue(out.toString().contains(key.idHex()), out.toString());
        assertEquals(1, run(env, "new"), "no overwrite without --force");
        assertTrue(err.toString().contains("--force"), err.toString());
        assertEquals(0, run(env, "show"));
        assertTrue(out.toString().contains("key-id " + key.idHex()));
        assertFalse(out.toString().contains(key.secretHex()), "show never prints the secret");
        assertTrue(out.toString().contains("--team-key " + dir.resolve("team.key")));
    }

    @Test
    void cHeaderAndBlobCarryTheKeyOwnerOnly() throws Exception {
        Path dir = tmp.resolve("keys");
        Map<String, String> env = Map.of();
        assertEquals(0, run(env, "new", "--keys", dir.toString()));
        TeamKey key = new KeyDir(dir).teamKey();
        Path header = tmp.resolve("team_key.h");
        Path blob = tmp.resolve("team_key.bin");
        assertEquals(0, run(env, "show", "--keys", dir.toString(), "--c-header", header.toString()));
        assertEquals(0, run(env, "show", "--keys", dir.toString(), "--blob", blob.toString()));
        String h = Files.readString(header);
        byte[] secret = HexFormat.of().parseHex(key.secretHex());
        assertTrue(h.contains(String.format("0x%02x, 0x%02x", secret[0] & 0xFF, secret[1] & 0xFF)), h);
        assertTrue(h.contains("touchline_team_key") && h.contains("key-id " + key.idHex()));
        byte[] b = Files.readAllBytes(blob);
        assertEquals(40, b.length);
        assertEquals("TLK1", new String(b, 0, 4, java.nio.charset.StandardCharsets.US_ASCII));
        assertArrayEquals(secret, Arrays.copyOfRange(b, 4, 36));
        assertArrayEquals(key.id(), Arrays.copyOfRange(b, 36, 40));
        assertEquals("rw-------", PosixFilePermissions.toString(Files.getPosixFilePermissions(header)));
        assertEquals("rw-------", PosixFilePermissions.toString(Files.getPosixFilePermissions(blob)));
        assertEquals(2, run(env, "show", "--keys", dir.toString(), "--c-header", "a.h", "--blob", "b.bin"),
                "one export at a time");
    }

    @Test
    void showWithoutKeysSaysWhatToDo() {
        assertEquals(1, run(Map.of(), "show", "--keys", tmp.resolve("none").toString()));
        assertTrue(err.toString().contains("touchline keys new"), err.toString());
    }

    @Test
    void aListeningCommandRefusesABrokenKeyAndContradictoryOptions() throws Exception {
        Path dir = tmp.resolve("keys");
        new KeyDir(dir).create(false, new java.security.SecureRandom(), java.time.Instant.now());
        Files.writeString(dir.resolve("team.key"), "team-key = 00\nkey-id = 00000000\n");
        StartFailure bad = assertThrows(StartFailure.class, () -> new KeyChoice(dir, false, Map.of()).security());
        assertTrue(bad.getMessage().contains("64 hex digits"), bad.getMessage());
        assertTrue(bad.getMessage().endsWith("To run without keys: --insecure"), bad.getMessage());
        assertThrows(StartFailure.class, () -> new KeyChoice(dir, true, Map.of()).security());
        assertTrue(new KeyChoice(null, true, Map.of()).security().key().isEmpty());
        assertTrue(new KeyChoice(null, false, Map.of("TOUCHLINE_KEYS", tmp.resolve("nothing").toString()))
                .security().key().isEmpty(), "no key in the default place: lab mode");
    }
}
