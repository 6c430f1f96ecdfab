package touchline.protocol.gamecontroller;

import java.util.Arrays;

/**
 * A robot's return packet as an HSL GameController forwards it to its registered monitors on
 * UDP 3940: the robot's IPv4 address (4 bytes, network order) followed by the 32 bytes the
 * robot sent. The packet is checked like the GameController checks it (version 4 only); an
 * address no robot can have as its source (0.x.x.x, multicast, 240.0.0.0 and above, the
 * broadcast address) is a rejection, because the prefix is what tells the robots apart.
 *
 * @param robotAddress the robot's IPv4 address, 4 bytes
 * @param packet       what the robot sent
 */
public record ForwardedReturnPacket(byte[] robotAddress, ReturnPacket.V4 packet) {

    public static final int SIZE = 4 + ReturnPacket.V4.SIZE;
    public static final int PORT = 3940;

    public ForwardedReturnPacket {
        if (robotAddress.length != 4) {
            throw new IllegalArgumentException("an IPv4 address has 4 bytes, got " + robotAddress.length);
        }
        robotAddress = robotAddress.clone();
    }

    @Override
    public byte[] robotAddress() {
        return robotAddress.clone();
    }

    /** The address in dotted form, e.g. {@code 10.0.5.12}. */
    public String robotHost() {
        return (robotAddress[0] & 0xFF) + "." + (robotAddress[1] & 0xFF) + "." + (robotAddress[2] & 0xFF) + "."
                + (robotAddress[3] & 0xFF);
    }

    public byte[] encode() {
        byte[] out = new byte[SIZE];
        System.arraycopy(robotAddress, 0, out, 0, 4);
        System.arraycopy(packet.encode(), 0, out, 4, ReturnPacket.V4.SIZE);
        return out;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof ForwardedReturnPacket f && Arrays.equals(robotAddress, f.robotAddress)
                && packet.equals(f.packet);
    }

    @Override
    public int hashCode() {
        return 31 * Arrays.hashCode(robotAddress) + packet.hashCode();
    }

    /** Decodes one datagram of port 3940; bad input is a reason, never an exception. */
    public static final class Decoder {

        private final ReturnPacketDecoder returns = new ReturnPacketDecoder(true);

        public Decoded<ForwardedReturnPacket> decode(byte[] datagram) {
            if (datagram == null || datagram.length != SIZE) {
                return Decoded.rejected(DecodeFailure.WRONG_LENGTH, "a forwarded return packet has " + SIZE
                        + " bytes (IPv4 address + 32), got " + (datagram == null ? 0 : datagram.length));
            }
            int first = datagram[0] & 0xFF;
            if (first == 0 || first >= 224) {
                return Decoded.rejected(DecodeFailure.INVALID_FIELD, "address prefix " + (datagram[0] & 0xFF) + "."
                        + (datagram[1] & 0xFF) + "." + (datagram[2] & 0xFF) + "." + (datagram[3] & 0xFF)
                        + " is not a robot's unicast IPv4 address");
            }
            Decoded<ReturnPacket> p = returns.decode(Arrays.copyOfRange(datagram, 4, SIZE));
            if (!p.isOk()) {
                return Decoded.rejected(p.failure(), "forwarded return packet: " + p.detail());
            }
            return Decoded.ok(new ForwardedReturnPacket(Arrays.copyOf(datagram, 4), (ReturnPacket.V4) p.value()));
        }
    }
}
