package touchline.transport.nao;

import org.zeromq.ZMQ;
import touchline.security.CurveKey;
import touchline.security.KeyDir;
import touchline.security.KeyException;
import touchline.security.KeyFile;

/**
 * What the console needs to talk CURVE to a NAO: its own client key pair ({@code console.secret})
 * and the NAO's server public key ({@code nao-server.public}), from one key directory
 * ({@link KeyDir}, which reads and checks the files).
 *
 * @param serverPublic the NAO robot side's public key
 * @param clientPublic this console's public key (the NAO lets it in when it holds console.public)
 * @param clientSecret this console's secret key
 */
public record NaoClientKeys(CurveKey serverPublic, CurveKey clientPublic, CurveKey clientSecret) {

    /** Reads and checks the two files in {@code dir}; the error names the file and the way out. */
    public static NaoClientKeys load(KeyDir dir) throws KeyException {
        KeyFile console = dir.read(KeyDir.CONSOLE_SECRET, true);
        KeyFile server = dir.read(KeyDir.NAO_SERVER_PUBLIC, false);
        return new NaoClientKeys(server.curveKey("public-key"), console.curveKey("public-key"),
                console.curveKey("secret-key"));
    }

    /** Makes {@code socket} a CURVE client with these keys (before it connects). */
    public void applyTo(ZMQ.Socket socket) {
        socket.setCurveServerKey(serverPublic.bytes());
        socket.setCurvePublicKey(clientPublic.bytes());
        socket.setCurveSecretKey(clientSecret.bytes());
    }
}
