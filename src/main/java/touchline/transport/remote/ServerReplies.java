package touchline.transport.remote;

import org.json.JSONObject;

import java.nio.ByteBuffer;

/**
 * What a stream hands on of the server's messages it does not handle itself: the JSON ops
 * beyond advertise, unadvertise, status and serverInfo (parameter values, services), and the
 * binary ones beyond message data and time (service call responses), and the status messages
 * that answer a request of its own (by their id).
 */
interface ServerReplies {

    /** Hears nothing. */
    ServerReplies NONE = new ServerReplies() {
        @Override
        public void op(JSONObject o) {
        }

        @Override
        public boolean binary(int op, ByteBuffer rest) {
            return false;
        }
    };

    /** A JSON op of the server's (called on the stream's thread). */
    void op(JSONObject o);

    /** A status op carrying an {@code id}: true when it answers a request of this client's (then it is not shown). */
    default boolean answer(JSONObject status) {
        return false;
    }

    /** A binary message of opcode {@code op}, {@code rest} after the opcode, little-endian; false when not understood. */
    boolean binary(int op, ByteBuffer rest);
}
