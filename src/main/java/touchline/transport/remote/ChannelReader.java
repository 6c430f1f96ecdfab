package touchline.transport.remote;

import org.json.JSONObject;

/**
 * Which advertised channels a stream subscribes to, and as what: another Touchline's robot
 * channels ({@link RemoteChannel}) or any server's channels as one robot's ({@link BridgedChannel}).
 */
@FunctionalInterface
interface ChannelReader {

    /**
     * The channel one entry of an {@code advertise} op lists, or null when it is not wanted
     * (skipped without a word); IllegalArgumentException saying why a wanted one cannot be read.
     */
    StreamChannel read(JSONObject advertised);
}
