package touchline.bench;

import java.util.Map;

/**
 * One measured phase of the ingest benchmark: datagrams sent, decoded, and decoded per second;
 * in drain mode also the receiving threads' CPU nanoseconds per decoded datagram, by role
 * ({@link ThreadCpu}; empty otherwise).
 */
record IngestResult(long sent, long received, double perSecond, Map<String, Double> cpuNanosPerMessage) {

    IngestResult(long sent, long received, double perSecond) {
        this(sent, received, perSecond, Map.of());
    }

    /** CPU per datagram of the busiest receiving thread (the others run beside it), NaN when not measured. */
    double busiestNanosPerMessage() {
        return cpuNanosPerMessage.entrySet().stream().filter(e -> !e.getKey().equals(ThreadCpu.OTHER))
                .mapToDouble(Map.Entry::getValue).max().orElse(Double.NaN);
    }

    /** The CPU figures as one line: {@code event loop 1510 ns, stage 980 ns, ...}. */
    String cpuText() {
        StringBuilder out = new StringBuilder();
        cpuNanosPerMessage.forEach((role, ns) -> out.append(out.length() == 0 ? "" : ", ")
                .append(role).append(' ').append(Math.round(ns)).append(" ns"));
        return out.toString();
    }
}
