package touchline.transport.remote;

import touchline.transport.Envelope;

import java.io.IOException;

/**
 * One channel a Foxglove WebSocket server advertised and this client subscribed to (under the
 * channel's own id), and how each of its payloads becomes an envelope.
 */
interface StreamChannel {

    int id();

    String topic();

    /** The envelope one message makes; {@code timeNanos} is the server's log time. IOException: unusable, counted. */
    Envelope rebuild(byte[] payload, long timeNanos) throws IOException;
}
