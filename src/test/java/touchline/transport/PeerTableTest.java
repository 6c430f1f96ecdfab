package touchline.transport;

import org.junit.jupiter.api.Test;
import touchline.protocol.Framing;

import java.net.InetSocketAddress;
import java.util.Optional;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Where a command to a robot goes: the address and framing learned from its datagrams. */
class PeerTableTest {

    private static InetSocketAddress at(int port) {
        return new InetSocketAddress("127.0.0.1", port);
    }

    @Test
    void withoutAFixedPortARobotIsAnsweredAtItsSourcePortInItsFraming() {
        PeerTable peers = new PeerTable(0);
        peers.learn(3, at(40003), Framing.LEGACY);

        assertEquals(Optional.of(new PeerTable.Peer(at(40003), Framing.LEGACY)), peers.peer(3));
        assertEquals(Optional.empty(), peers.peer(4));
    }

    @Test
    void withAFixedPortARobotIsAnsweredAtThatPortOfItsHost() {
        PeerTable peers = new PeerTable(3838);
        peers.learn(3, at(51234), Framing.LENGTH_PREFIX);

        assertEquals(Optional.of(new PeerTable.Peer(at(3838), Framing.LENGTH_PREFIX)), peers.peer(3));
        assertEquals(Optional.of(3), peers.robotAt(at(60000)), "with a fixed port the host names the robot");
    }

    @Test
    void aRobotThatMovesOrChangesItsFramingIsFollowed() {
        PeerTable peers = new PeerTable(0);
        peers.learn(3, at(40003), Framing.LEGACY);
        peers.learn(3, at(40013), Framing.LEGACY);
        assertEquals(at(40013), peers.peer(3).orElseThrow().address());

        peers.learn(3, at(40013), Framing.LENGTH_PREFIX);
        assertEquals(Framing.LENGTH_PREFIX, peers.peer(3).orElseThrow().framing());
        assertEquals(Optional.empty(), peers.robotAt(at(40003)), "the old address no longer names it");
        assertEquals(Optional.of(3), peers.robotAt(at(40013)));
    }

    @Test
    void aRobotHeardOnlyUntaggedIsNoDestinationUntilItIsHeardTagged() {
        PeerTable peers = new PeerTable(0);
        peers.untagged(5);
        assertTrue(peers.isUntagged(5));
        assertEquals(Optional.empty(), peers.peer(5));

        peers.learn(5, at(40005), Framing.LEGACY);
        assertFalse(peers.isUntagged(5));
        peers.untagged(5);
        assertFalse(peers.isUntagged(5), "a forgery under its number does not take a known robot's address away");
        assertEquals(at(40005), peers.peer(5).orElseThrow().address());
    }
}
