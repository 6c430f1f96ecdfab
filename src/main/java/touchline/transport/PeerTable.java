package touchline.transport;

import touchline.protocol.Framing;

import java.net.InetSocketAddress;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Where each robot is and which framing it speaks, learned from its datagrams, so a
 * command goes to its current address in the header format it uses. With a fixed robot
 * port (3838 on a real field) replies go to that port; otherwise to the datagram's source
 * port (simulated robots share one host and listen on different ports).
 */
public final class PeerTable {

    /** A robot's address and framing as last seen. */
    public record Peer(InetSocketAddress address, Framing framing) { }

    private final Map<Integer, Peer> peers = new ConcurrentHashMap<>();
    /** Robots heard untagged by a console with a key: never a command destination. */
    private final java.util.Set<Integer> untagged = ConcurrentHashMap.newKeySet();
    private final int fixedRobotPort;

    /** @param fixedRobotPort the port robots listen on, or 0 to reply to each datagram's source port */
    public PeerTable(int fixedRobotPort) {
        this.fixedRobotPort = fixedRobotPort;
    }

    public void learn(int robotId, InetSocketAddress source, Framing framing) {
        if (!untagged.isEmpty()) {
            untagged.remove(robotId);
        }
        Peer before = peers.get(robotId);
        if (before != null && before.framing() == framing && sameTarget(before.address(), source)) {
            return; // the usual case, once per datagram: nothing to allocate
        }
        InetSocketAddress target = fixedRobotPort == 0 ? source : new InetSocketAddress(source.getAddress(), fixedRobotPort);
        peers.put(robotId, new Peer(target, framing));
    }

    private boolean sameTarget(InetSocketAddress known, InetSocketAddress source) {
        return (fixedRobotPort != 0 || known.getPort() == source.getPort())
                && java.util.Objects.equals(known.getAddress(), source.getAddress());
    }

    /** The robot last seen at this address (with a fixed robot port: at this host), if any. */
    public Optional<Integer> robotAt(InetSocketAddress address) {
        for (Map.Entry<Integer, Peer> e : peers.entrySet()) {
            if (sameTarget(e.getValue().address(), address)) {
                return Optional.of(e.getKey());
            }
        }
        return Optional.empty();
    }

    /** An untagged datagram claiming this robot reached a console with a key: its address is not learned. */
    public void untagged(int robotId) {
        untagged.add(robotId);
    }

    /** True when the robot was heard only untagged by a console with a key. */
    public boolean isUntagged(int robotId) {
        return untagged.contains(robotId) && !peers.containsKey(robotId);
    }

    public Optional<Peer> peer(int robotId) {
        return Optional.ofNullable(peers.get(robotId));
    }
}
