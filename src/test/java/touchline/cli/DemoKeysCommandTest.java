package touchline.cli;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;
import touchline.transport.nao.NaoClientKeys;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The demo's key files: made once, kept while readable, made anew when damaged. */
class DemoKeysCommandTest {

    @TempDir
    Path dir;

    private final StringWriter err = new StringWriter();

    private int run(Path keys) {
        CommandLine cli = new CommandLine(new DemoKeysCommand());
        cli.setOut(new PrintWriter(new StringWriter(), true));
        cli.setErr(new PrintWriter(err, true));
        return cli.execute(keys.toString());
    }

    @Test
    void makesKeepsAndRepairs() throws Exception {
        Path keys = dir.resolve("demo-keys");
        assertEquals(0, run(keys));
        NaoClientKeys first = NaoClientKeys.load(keys);
        assertEquals(0, run(keys));
        assertEquals(first, NaoClientKeys.load(keys), "kept: the running simulated NAO still has them");
        Files.writeString(keys.resolve("console.secret"), "public-key = short\n");
        assertEquals(0, run(keys));
        assertTrue(err.toString().contains("making new demo keys"), err.toString());
        assertNotEquals(first.clientPublic(), NaoClientKeys.load(keys).clientPublic());
    }
}
