package touchline.app;

import touchline.transport.TrafficCounters;

/**
 * The UDP transport's counts at one moment, for the status bar and the commands: datagrams and
 * bytes in (the team's own team messages included, when the budget guard hears them) and out, malformed, held back by match mode, forged and unverified (with a team key).
 * A value: the faces read it from {@link LiveField#transportCounts()}, never the transport's counters.
 */
public record TransportCounts(long datagramsIn, long bytesIn, long datagramsOut, long bytesOut, long malformedIn,
                              long held, long forgedIn, long unverifiedIn) {

    static TransportCounts of(TrafficCounters c, long teamDatagrams, long teamBytes) {
        return new TransportCounts(c.datagramsIn() + teamDatagrams, c.bytesIn() + teamBytes, c.datagramsOut(),
                c.bytesOut(), c.malformedIn(), c.held(), c.forgedIn(), c.unverifiedIn());
    }
}
