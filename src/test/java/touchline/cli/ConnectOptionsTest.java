package touchline.cli;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.*;

/** {@code --connect} and {@code --trust-cert} that cannot work end the command with one sentence, before any window. */
@Tag("integration")
class ConnectOptionsTest {

    @TempDir
    Path dir;

    private static String[] run(String... args) {
        StringWriter err = new StringWriter();
        int code = Main.execute(args, new PrintWriter(err, true));
        return new String[]{Integer.toString(code), err.toString()};
    }

    private static void oneSentence(String[] r, String words) {
        assertEquals(Integer.toString(StartFailure.BAD_INPUT), r[0], r[1]);
        assertTrue(r[1].contains(words), r[1]);
        assertFalse(r[1].contains("\tat "), r[1]);
    }

    @Test
    void aUrlThatIsNotAWebSocketOneIsSaid() {
        oneSentence(run("listen", "--connect", "http://127.0.0.1:8765/", "--seconds", "1"), "not a WebSocket URL");
        oneSentence(run("console", "--connect", "ws://bad host/", "--layouts", dir.toString()), "not a URL");
    }

    @Test
    void aCertificateFileWithoutACertificateIsSaid() throws Exception {
        Path notACert = Files.writeString(dir.resolve("cert.pem"), "hello");
        oneSentence(run("listen", "--connect", "wss://127.0.0.1:8765/", "--trust-cert", notACert.toString(),
                "--seconds", "1"), "cert.pem");
    }
}
