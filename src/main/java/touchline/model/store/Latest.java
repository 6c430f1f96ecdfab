package touchline.model.store;

import com.google.protobuf.Message;

/**
 * The newest data message of one robot's option, with the receive time of its datagram (for
 * packet-to-screen latency) and a per-key version so a view redraws only when it changed.
 */
public record Latest(int robotId, String option, String kind, Message data, long timeMicros, long version) { }
