package touchline.cli;

import picocli.CommandLine.Option;
import touchline.app.Console;
import touchline.app.ConsoleConfig;
import touchline.app.bridges.BridgeAddress;
import touchline.app.bridges.RosBridges;
import touchline.app.bridges.ServerKind;
import touchline.app.bridges.TeamFile;
import touchline.transport.UdpConfig;
import touchline.transport.remote.RemoteTrust;

import javax.net.ssl.SSLContext;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * {@code --connect URL… [--ros-team FILE] [--trust-cert FILE]} ({@code listen}, {@code console}):
 * a lone URL of another Touchline is watched instead of the field (the console then hears no
 * robot itself and sends nothing); every other URL, {@code NAME=URL}, and every robot of a
 * team file is a ROS 2 robot's Foxglove bridge, a robot of this console beside the UDP robots.
 */
final class RemoteOptions {

    @Option(names = "--connect", paramLabel = "URL", arity = "1..*",
            description = "a robot's Foxglove bridge (ROS 2 foxglove_bridge, any Foxglove SDK server): ws://HOST:8765/"
                    + " or NAME=ws://…, several allowed, each a robot beside the UDP robots; or one remote Touchline"
                    + " (touchline serve, a window serving to viewers: ws://HOST:8765/?token=…), watched instead of the"
                    + " field with commands off; a lost connection reconnects by itself")
    List<String> connect = new ArrayList<>();

    @Option(names = "--ros-team", paramLabel = "FILE",
            description = "a team of ROS 2 robots (their bridges' names and URLs, and a mapping of their topics) in a"
                    + " JSON file, e.g. samples/ros2-team.json")
    Path team;

    @Option(names = "--trust-cert", paramLabel = "FILE",
            description = "for wss://: trust the server's certificate in this PEM file (e.g. a self-signed one)")
    Path trustCert;

    private Boolean viewing;
    private TeamFile teamRead;

    /** Checks every URL, the certificate and the team file before anything starts: one sentence for the user when bad. */
    void check() throws StartFailure {
        for (String c : connect) {
            address(c);
        }
        tls();
        if (team != null) {
            try {
                teamRead = TeamFile.read(team);
            } catch (IOException e) {
                throw StartFailure.badInput(e.getMessage());
            }
        }
    }

    /** Whether the console views another Touchline (one bare URL whose server is a Touchline). */
    boolean remote() throws InterruptedException {
        if (viewing == null) {
            try {
                viewing = connect.size() == 1 && team == null && !connect.get(0).contains("=ws")
                        && new ServerKind(address(connect.get(0)).url(), tls()).isTouchline();
            } catch (StartFailure e) {
                viewing = false; // a bad URL or certificate: said when the bridges are connected
            }
        }
        return viewing;
    }

    private static BridgeAddress address(String text) throws StartFailure {
        try {
            return BridgeAddress.parse(text);
        } catch (IllegalArgumentException e) {
            throw StartFailure.badInput(e.getMessage());
        }
    }

    private SSLContext tls() throws StartFailure {
        try {
            return trustCert == null ? null : RemoteTrust.trusting(trustCert);
        } catch (IOException e) {
            throw StartFailure.badInput(e.getMessage());
        }
    }

    /** A console that hears nothing from the field, viewing the one URL; one sentence for the user when it cannot. */
    Console startViewing() throws InterruptedException, StartFailure {
        BridgeAddress a = address(connect.get(0));
        Console console = new Console(ConsoleConfig.defaults().withGameControllerPort(0)
                .withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0)));
        try {
            console.start();
            console.remote().view(a.url(), tls());
            return console;
        } catch (IllegalArgumentException e) {
            console.close();
            throw StartFailure.badInput(e.getMessage());
        }
    }

    /** Connects the console to every bridge named (not when it views a Touchline); a bad URL or team file stops the start. */
    void connectBridges(RosBridges bridges) throws InterruptedException, StartFailure {
        if (remote()) {
            return;
        }
        SSLContext tls = tls();
        if (team != null) {
            if (teamRead == null) {
                check();
            }
            bridges.connect(teamRead, tls);
        }
        for (String c : connect) {
            bridges.connect(address(c), tls);
        }
    }
}
