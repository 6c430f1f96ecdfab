package touchline.transport.nao;

import java.util.List;

/**
 * What a {@link CallDispatcher} needs of the connection to the robot ({@link NaoConnection} on
 * the wire, a test's fake without sockets): send a request, take a reply or a monitor event
 * when one is waiting, start afresh. Used only under the link's lock.
 */
interface LinkWire {

    /** Sends {@code [id][""][payload]} without waiting; false when nothing could be queued. */
    boolean send(long id, byte[] payload);

    /** The frames of the next reply, or null when none is waiting. */
    List<byte[]> receive();

    /** The next monitor event, or null when none is waiting. */
    NaoConnection.Event nextEvent();

    /** Drops the connection and everything it still held, and connects anew. */
    void reopen();
}
