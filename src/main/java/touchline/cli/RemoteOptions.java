package touchline.cli;

import picocli.CommandLine.Option;
import touchline.app.Console;
import touchline.app.ConsoleConfig;
import touchline.transport.UdpConfig;
import touchline.transport.remote.RemoteTrust;

import java.io.IOException;
import java.net.URI;
import java.net.URISyntaxException;
import java.nio.file.Path;

/**
 * {@code --connect URL [--trust-cert FILE]}: watch another Touchline's stream instead of the
 * field ({@code listen}, {@code console}). The console then hears no robot itself (its UDP port
 * is a loopback one nobody sends to) and sends nothing.
 */
final class RemoteOptions {

    @Option(names = "--connect", paramLabel = "URL",
            description = "watch a remote Touchline (touchline serve, or a window serving to viewers): "
                    + "ws://HOST:8765/?token=… or wss://…; commands are off (but options --on/--off, which that Touchline"
                    + " switches for a tool on its own machine), a lost connection reconnects by itself")
    String connect;

    @Option(names = "--trust-cert", paramLabel = "FILE",
            description = "for wss://: trust the server's certificate in this PEM file (e.g. a self-signed one)")
    Path trustCert;

    boolean remote() {
        return connect != null;
    }

    /** A console that hears nothing from the field, viewing {@link #connect}; one sentence for the user when it cannot. */
    Console startViewing() throws InterruptedException, StartFailure {
        URI url;
        try {
            url = new URI(connect);
        } catch (URISyntaxException e) {
            throw StartFailure.badInput("not a URL: " + connect + " (" + e.getReason() + ")");
        }
        Console console = new Console(ConsoleConfig.defaults().withGameControllerPort(0)
                .withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0)));
        try {
            console.start();
            console.remote().view(url, trustCert == null ? null : RemoteTrust.trusting(trustCert));
            return console;
        } catch (IOException | IllegalArgumentException e) {
            console.close();
            throw StartFailure.badInput(e.getMessage());
        }
    }
}
