package touchline.security;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.zeromq.SocketType;
import org.zeromq.ZContext;
import org.zeromq.ZMQ;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.SecureRandom;
import java.time.Instant;
import java.util.Map;
import java.util.Optional;

import static org.junit.jupiter.api.Assertions.*;

class KeyDirTest {

    @TempDir
    Path tmp;

    private KeyDir made() throws KeyException {
        KeyDir dir = new KeyDir(tmp.resolve("keys"));
        dir.create(false, new SecureRandom(), Instant.parse("2026-12-01T23:00:00Z"));
        return dir;
    }

    private static String perms(Path p) throws Exception {
        return PosixFilePermissions.toString(Files.getPosixFilePermissions(p));
    }

    @Test
    void writesFiveFilesOwnerOnlyAndReadsTheTeamKeyBack() throws Exception {
        KeyDir dir = made();
        assertEquals("rwx------", perms(dir.path()));
        for (String secret : new String[]{KeyDir.TEAM_KEY, KeyDir.NAO_SERVER_SECRET, KeyDir.CONSOLE_SECRET}) {
            assertEquals("rw-------", perms(dir.file(secret)), secret);
        }
        for (String pub : new String[]{KeyDir.NAO_SERVER_PUBLIC, KeyDir.CONSOLE_PUBLIC}) {
            assertEquals("rw-r--r--", perms(dir.file(pub)), pub);
        }
        String text = Files.readString(dir.file(KeyDir.TEAM_KEY));
        assertTrue(text.startsWith("#"), "a comment says what the file is");
        assertTrue(text.contains("2026-12-01T23:00:00Z"), "and when it was made");
        TeamKey key = dir.teamKey();
        assertTrue(text.contains("team-key = " + key.secretHex()));
        assertTrue(text.contains("key-id = " + key.idHex()));
        assertEquals(key.idHex(), new KeyDir(dir.path()).teamKey().idHex());
    }

    @Test
    void refusesToOverwriteWithoutForceAndMakesANewKeyWithIt() throws Exception {
        KeyDir dir = made();
        TeamKey first = dir.teamKey();
        KeyException e = assertThrows(KeyException.class, () -> dir.create(false, new SecureRandom(), Instant.now()));
        assertTrue(e.getMessage().contains("--force"), e.getMessage());
        assertEquals(first.idHex(), dir.teamKey().idHex(), "nothing was touched");
        TeamKey second = dir.create(true, new SecureRandom(), Instant.now());
        assertNotEquals(first.idHex(), second.idHex());
    }

    @Test
    void missingCorruptWrongLengthAndOpenFilesGiveClearMessages() throws Exception {
        KeyDir empty = new KeyDir(tmp.resolve("none"));
        assertTrue(assertThrows(KeyException.class, empty::teamKey).getMessage().contains("touchline keys new"));

        KeyDir dir = made();
        Path f = dir.file(KeyDir.TEAM_KEY);
        String good = Files.readString(f);
        String hex = dir.teamKey().secretHex();

        Files.writeString(f, good.replace(hex, hex.substring(0, 62)));
        assertTrue(assertThrows(KeyException.class, dir::teamKey).getMessage().contains("64 hex digits"));
        Files.writeString(f, good.replace(hex, "zz" + hex.substring(2)));
        assertTrue(assertThrows(KeyException.class, dir::teamKey).getMessage().contains("non-hex"));
        Files.writeString(f, good.replace(hex, (hex.charAt(0) == '0' ? "1" : "0") + hex.substring(1)));
        assertTrue(assertThrows(KeyException.class, dir::teamKey).getMessage().contains("does not belong"));
        Files.writeString(f, "garbage without equals\n");
        assertTrue(assertThrows(KeyException.class, dir::teamKey).getMessage().contains("line 1"));
        Files.write(f, new byte[]{(byte) 0xC3, (byte) 0x28, '\n'});
        assertTrue(assertThrows(KeyException.class, dir::teamKey).getMessage().contains("not UTF-8"));

        Files.writeString(f, good);
        Files.setPosixFilePermissions(f, PosixFilePermissions.fromString("rw-r--r--"));
        assertTrue(assertThrows(KeyException.class, dir::teamKey).getMessage().contains("chmod 600"));
    }

    @Test
    void locateTakesTheOptionThenTheEnvironmentThenTheConfigDirectory() {
        Path opt = tmp.resolve("opt");
        assertEquals(opt, KeyDir.locate(Optional.of(opt), Map.of("TOUCHLINE_KEYS", "/env")).path());
        assertEquals(Path.of("/env"), KeyDir.locate(Optional.empty(), Map.of("TOUCHLINE_KEYS", "/env")).path());
        assertEquals(Path.of("/xdg/touchline/keys"),
                KeyDir.locate(Optional.empty(), Map.of("XDG_CONFIG_HOME", "/xdg", "HOME", "/home/u")).path());
        assertEquals(Path.of("/home/u/.config/touchline/keys"),
                KeyDir.locate(Optional.empty(), Map.of("HOME", "/home/u")).path());
    }

    @Test
    void theCounterStoreSurvivesARestartAndADamagedFileCountsAsZero() throws Exception {
        KeyDir dir = made();
        assertEquals(123_456L, dir.counterStore().take(123_456L));
        assertEquals(123_457L, new KeyDir(dir.path()).counterStore().take(5), "one above the last, after a restart");
        Files.writeString(dir.file(KeyDir.COUNTER), "not a number");
        assertEquals(7L, dir.counterStore().take(7));
    }

    @Test
    void theBootStoreKeepsTheHighestBootOfEachRobotAcrossRestartsAndSkipsDamagedLines() throws Exception {
        KeyDir dir = made();
        dir.bootStore().raise(3, 7);
        dir.bootStore().raise(3, 5);
        dir.bootStore().raise(4, 0xF000_0000);
        assertEquals(Map.of(3, 7, 4, 0xF000_0000), new KeyDir(dir.path()).bootStore().load());
        Files.writeString(dir.file(KeyDir.BOOTS), "robot 3 = 9\nrobot x = 2\ngarbage\n");
        assertEquals(Map.of(3, 9), dir.bootStore().load());
    }

    /** The CURVE pairs are real libzmq keys: a CURVE client and server complete a handshake with them. */
    @Test
    void curveKeyPairsWorkForAZeroMqHandshake() throws Exception {
        KeyDir dir = made();
        KeyFile server = dir.read(KeyDir.NAO_SERVER_SECRET, true);
        KeyFile client = dir.read(KeyDir.CONSOLE_SECRET, true);
        assertEquals(server.curveKey("public-key"), dir.read(KeyDir.NAO_SERVER_PUBLIC, false).curveKey("public-key"));
        assertEquals(client.curveKey("public-key"), dir.read(KeyDir.CONSOLE_PUBLIC, false).curveKey("public-key"));
        try (ZContext ctx = new ZContext()) {
            ZMQ.Socket rep = ctx.createSocket(SocketType.REP);
            rep.setCurveServer(true);
            rep.setCurveSecretKey(server.curveKey("secret-key").bytes());
            int port = rep.bindToRandomPort("tcp://127.0.0.1");
            ZMQ.Socket req = ctx.createSocket(SocketType.REQ);
            req.setCurveServerKey(server.curveKey("public-key").bytes());
            req.setCurvePublicKey(client.curveKey("public-key").bytes());
            req.setCurveSecretKey(client.curveKey("secret-key").bytes());
            req.setReceiveTimeOut(5000);
            rep.setReceiveTimeOut(5000);
            req.connect("tcp://127.0.0.1:" + port);
            req.send("ping");
            assertEquals("ping", rep.recvStr());
            rep.send("pong");
            assertEquals("pong", req.recvStr());
        }
    }
}
