package touchline.transport.gamecontroller;

import java.util.Locale;

/**
 * What the embedded GameController's monitor service did so far, for its status line.
 *
 * @param monitors    registered now
 * @param capacity    the most that can be registered at once
 * @param leaseMs     how long a registration lasts after its host's last request
 * @param refusedFull requests refused because the table was full
 * @param badRequests requests that did not decode or came from a robot (counted, not applied)
 * @param expired     registrations forgotten because their host stopped asking
 * @param dropped     datagrams for the monitors dropped because their send queue was full
 */
public record MonitorStats(int monitors, int capacity, long leaseMs, long refusedFull, long badRequests,
                           long expired, long dropped) {

    /** One line: "2 of 32 monitors (60 s lease); refused: 0 table full, 1 bad; 3 expired; 0 datagrams … dropped". */
    public String describe() {
        return String.format(Locale.ROOT, "%d of %d monitors (%s lease); refused: %d table full, %d bad; "
                        + "%d expired; %d datagrams to monitors dropped", monitors, capacity, lease(leaseMs),
                refusedFull, badRequests, expired, dropped);
    }

    /** A lease in words: "60 s", or "300 ms" when it is no whole number of seconds. */
    static String lease(long leaseMs) {
        return leaseMs % 1000 == 0 ? leaseMs / 1000 + " s" : leaseMs + " ms";
    }
}
