package touchline.transport.nao;

import org.junit.jupiter.api.Test;
import touchline.proto.Nao.HAWActorRPCResponse;

import java.nio.ByteBuffer;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The robot's replies read alone: frames in, the request id and the call's outcome out. */
class ReplyReaderTest {

    private static byte[] id(long id) {
        return ByteBuffer.allocate(8).putLong(id).array();
    }

    @Test
    void aReplyNamesItsRequestAndGivesTheOutcome() {
        ReplyReader reader = new ReplyReader();
        byte[] error = HAWActorRPCResponse.newBuilder().setError("ALMotion: no method 'fly'").build().toByteArray();
        ReplyReader.Read read = reader.read(List.of(id(42), new byte[0], error));
        ReplyReader.Reply reply = assertInstanceOf(ReplyReader.Reply.class, read);
        assertEquals(42, reply.id());
        assertEquals(new CallOutcome.Failed("ALMotion: no method 'fly'"), reader.outcomeOf(reply.response()));
        assertEquals(new CallOutcome.Done(), reader.outcomeOf(HAWActorRPCResponse.getDefaultInstance()));
        assertEquals(0, reader.malformed());
    }

    @Test
    void wrongFramesAreMalformedWithoutARequest() {
        ReplyReader reader = new ReplyReader();
        ReplyReader.Malformed m = assertInstanceOf(ReplyReader.Malformed.class,
                reader.read(List.of(new byte[] {1, 2, 3}, new byte[0], new byte[0])));
        assertEquals(-1, m.id());
        assertEquals("expected [8-byte id][empty][reply], got 3 frames", m.why());
        assertInstanceOf(ReplyReader.Malformed.class, reader.read(List.of(new byte[] {7})));
        assertEquals(2, reader.malformed());
    }

    @Test
    void anUnparsableResponseFailsItsCallWithTheReason() {
        ReplyReader reader = new ReplyReader();
        // field 1 (the return value) claims 100 bytes and has 1
        ReplyReader.Malformed m = assertInstanceOf(ReplyReader.Malformed.class,
                reader.read(List.of(id(7), new byte[0], new byte[] {0x0a, 100, 1})));
        assertEquals(7, m.id());
        assertTrue(m.why().startsWith("unreadable HAWActorRPCResponse: "), m.why());
        assertTrue(m.callError().startsWith("unreadable reply: "), m.callError());
        assertEquals(1, reader.malformed());
    }
}
