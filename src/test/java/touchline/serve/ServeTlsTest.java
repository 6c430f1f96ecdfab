package touchline.serve;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.app.Console;
import touchline.app.ConsoleConfig;
import touchline.testing.Await;
import touchline.transport.UdpConfig;
import touchline.transport.remote.RemoteStatus;
import touchline.transport.remote.RemoteTrust;

import java.io.FileInputStream;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.KeyStore;
import java.util.Base64;

import static org.junit.jupiter.api.Assertions.*;

/**
 * {@code wss://}: the server with a PEM certificate and key (self-signed, made here with the
 * JDK's own keytool), a Touchline viewer that trusts exactly that certificate receives the
 * stream, one that does not is told why and receives nothing.
 */
@Tag("integration")
class ServeTlsTest {

    /** A self-signed certificate for 127.0.0.1 as cert.pem and key.pem (PKCS#8) in {@code dir}. */
    static Path[] selfSigned(Path dir) throws Exception {
        Path store = dir.resolve("server.p12");
        String keytool = Path.of(System.getProperty("java.home"), "bin", "keytool").toString();
        Process p = new ProcessBuilder(keytool, "-genkeypair", "-alias", "touchline", "-keyalg", "EC", "-groupname",
                "secp256r1", "-dname", "CN=localhost", "-ext", "san=ip:127.0.0.1,dns:localhost", "-validity", "2",
                "-storetype", "PKCS12", "-keystore", store.toString(), "-storepass", "changeit", "-keypass", "changeit")
                .redirectErrorStream(true).start();
        String said = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertEquals(0, p.waitFor(), said);
        KeyStore ks = KeyStore.getInstance("PKCS12");
        try (FileInputStream in = new FileInputStream(store.toFile())) {
            ks.load(in, "changeit".toCharArray());
        }
        Path cert = dir.resolve("cert.pem");
        Path key = dir.resolve("key.pem");
        Files.writeString(cert, pem("CERTIFICATE", ks.getCertificate("touchline").getEncoded()));
        Files.writeString(key, pem("PRIVATE KEY", ks.getKey("touchline", "changeit".toCharArray()).getEncoded()));
        return new Path[]{cert, key};
    }

    private static String pem(String type, byte[] der) {
        return "-----BEGIN " + type + "-----\n" + Base64.getMimeEncoder(64, "\n".getBytes(StandardCharsets.US_ASCII))
                .encodeToString(der) + "\n-----END " + type + "-----\n";
    }

    @TempDir
    static Path dir;
    private static Path[] pem;

    /** One certificate for the class: keytool is a JVM of its own, seconds on a busy machine. */
    @org.junit.jupiter.api.BeforeAll
    static void certificate() throws Exception {
        pem = selfSigned(dir);
    }

    private static Console viewer() throws InterruptedException {
        return new Console(ConsoleConfig.defaults().withGameControllerPort(0)
                .withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0))).start();
    }

    @Test
    void aViewerTrustingTheCertificateWatchesOverTlsAndOneThatDoesNotIsToldWhy() throws Exception {
        try (ServedField field = new ServedField(ServeConfig.defaults().withPort(0).withTls(pem[0], pem[1]));
             Console trusting = viewer(); Console doubting = viewer()) {
            String url = field.server().url("127.0.0.1");
            assertTrue(url.startsWith("wss://"), url);
            trusting.remote().view(new URI(url), RemoteTrust.trusting(pem[0]));
            doubting.remote().view(new URI(url), null);
            Await.until("robot 5 over TLS", () -> {
                field.publish(ServedField.status(5, "tls", 40), "status");
                return trusting.field().robots().robot(5).isPresent();
            });
            assertEquals("tls", trusting.field().robots().robot(5).orElseThrow().name());
            Await.until("the doubting viewer is refused",
                    () -> doubting.remote().stream().orElseThrow().status().state() == RemoteStatus.State.LOST);
            assertFalse(doubting.remote().stream().orElseThrow().status().detail().isEmpty());
            assertTrue(doubting.field().robots().robots().isEmpty());
        }
    }

    @Test
    void aKeyThatIsNotOneIsASentenceNotAStackTrace() throws Exception {
        Path notAKey = Files.writeString(dir.resolve("not-a-key.pem"), "not a key");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new FoxgloveServer(
                ServeConfig.defaults().withPort(0).withTls(pem[0], notAKey), new touchline.protocol.MessageKinds(),
                new touchline.app.SystemClock()));
        assertTrue(e.getMessage().contains("cannot use the TLS certificate"), e.getMessage());
    }
}
