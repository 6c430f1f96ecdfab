package touchline.app;

import touchline.transport.UdpBackend;

import java.util.List;

/**
 * What this Touchline runs on, said in the window (Help → About, the status bar) and by
 * {@code --version}: the version, the Java runtime and system, the UDP transport (epoll with
 * recvmmsg on Linux, NIO as the portable fallback) and whether the GameController's sender can
 * get real-time priority (Linux) or keeps normal priority (the portable fallback).
 *
 * @param version          the product version
 * @param java             e.g. "Java 17.0.15 (Debian)"
 * @param system           e.g. "Linux 6.1 amd64"
 * @param udp              the console's UDP transport and why
 * @param realtimeUnavailable "" when real-time priority may be had here, else why normal priority
 * @param udpCores         where the transport's two ingest threads run (e.g. "ingest threads on
 *                         CPUs 0 | 1", {@code transport.CoreSplit}), "" when there is nothing to say
 */
public record RuntimeReport(ProductVersion version, String java, String system, UdpBackend udp,
                            String realtimeUnavailable, String udpCores) {

    public RuntimeReport(ProductVersion version, String java, String system, UdpBackend udp, String realtimeUnavailable) {
        this(version, java, system, udp, realtimeUnavailable, "");
    }

    /** The same report, saying where the ingest threads of a started transport run. */
    public RuntimeReport withUdpCores(String cores) {
        return new RuntimeReport(version, java, system, udp, realtimeUnavailable, cores);
    }

    /** This process, for a console on {@code udp}. */
    /**
     * This process with {@code udp} as its transport: whether the GameController sender may run at
     * real-time priority is asked of the system here.
     */
    public static RuntimeReport ofThisProcess(UdpBackend udp) {
        return ofThisProcess(udp, new touchline.transport.gamecontroller.RealtimePriority(10).unavailable());
    }

    public static RuntimeReport ofThisProcess(UdpBackend udp, String realtimeUnavailable) {
        return new RuntimeReport(ProductVersion.ofThisBuild(),
                "Java " + System.getProperty("java.runtime.version", System.getProperty("java.version", "?"))
                        + " (" + System.getProperty("java.vendor", "?") + ")",
                System.getProperty("os.name", "?") + " " + System.getProperty("os.version", "") + " "
                        + System.getProperty("os.arch", ""),
                udp, realtimeUnavailable);
    }

    /** The GameController sender's priority in a few words. */
    public String priority() {
        return realtimeUnavailable.isEmpty() ? "real-time priority when the system grants it (Linux, CAP_SYS_NICE)"
                : "normal priority (" + realtimeUnavailable + ")";
    }

    /** One short phrase for the status bar, e.g. "NIO · normal priority". */
    public String portability() {
        return udp.kind().title() + " · " + (realtimeUnavailable.isEmpty() ? "real-time capable" : "normal priority");
    }

    /** The lines of Help → About and of {@code --version}. */
    public List<String> lines() {
        return List.of(version.title(), java + ", " + system.trim(),
                "UDP transport: " + udp.describe() + (udpCores.isEmpty() ? "" : "; " + udpCores),
                "GameController sender: " + priority());
    }
}
