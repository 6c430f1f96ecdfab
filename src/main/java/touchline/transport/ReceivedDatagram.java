package touchline.transport;

import touchline.protocol.DatagramClass;

import java.net.InetSocketAddress;

/** A datagram taken off the socket, time-stamped and classified, before decoding. */
public record ReceivedDatagram(long timeMicros, InetSocketAddress sender, byte[] bytes, DatagramClass datagramClass) { }
