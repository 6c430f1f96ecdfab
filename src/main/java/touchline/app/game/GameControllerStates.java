package touchline.app.game;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import touchline.protocol.gamecontroller.Decoded;
import touchline.protocol.gamecontroller.GameControlData;
import touchline.protocol.gamecontroller.KnownGameStateFormats;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;
import touchline.transport.MicrosClock;
import touchline.transport.gamecontroller.BadPackets;
import touchline.transport.gamecontroller.MonitorRegistrations;

import java.net.InetSocketAddress;

/**
 * The one source of GameController game states for {@link MatchMode}: the state this console's
 * own GameController sends ({@link #own}) and every datagram heard on the game-state port
 * ({@link #datagram}, from the one listener there, {@link GameStateWatch}). Robots' reports
 * ({@code ReportedGameState}) and a remote console's GameController ({@code RemoteGameState})
 * are match mode's other inputs, each with its own label.
 * <p>
 * While it only listens, the field's GameController is pinned ({@link GameControllerSources}):
 * its states are believed; others are intruders, published with the reason and counted, yet heard
 * by match mode, where a claim of play from anyone keeps the console silent. True data from a
 * GameController this console did not register with is refused. While this console referees
 * ({@link #referee}), its own packets heard back are ignored, every other GameController is a
 * rival in the same table ({@link GameControllerSources#others()}, one window), and a datagram
 * that is no game state goes to the referee (return packets on the 2014 profiles' shared port).
 * Every game state heard becomes one IN envelope.
 */
public final class GameControllerStates {

    /** This console's own GameController while it referees. */
    public interface Referee {

        /** Whether {@code from} is this GameController's own sender (its packets heard back). */
        boolean ownPacket(InetSocketAddress from);

        /** A GameController not heard within the window began sending; {@code warning} says so. */
        void rivalHeard(String warning);

        /** A datagram on the port that is no game state (a return packet where they share the port). */
        void otherDatagram(byte[] data, InetSocketAddress from);
    }

    /** How match mode names this console's own GameController. */
    public static final String OWN_SOURCE = "this console's GameController";
    private static final Logger LOG = LoggerFactory.getLogger(GameControllerStates.class);

    private final KnownGameStateFormats formats = new KnownGameStateFormats();
    private final EnvelopeSink sink;
    private final MatchMode matchMode;
    private final MonitorRegistrations registrations;
    private final GameControllerSources sources;
    private final BadPackets badPackets;
    private final MicrosClock stamps;
    private volatile Referee referee;

    /**
     * @param sink          receives one GAMECONTROLLER envelope per game-state datagram
     * @param matchMode     told each state (may be null: nobody acts on it)
     * @param registrations the GameControllers whose true data ("RGTD") this console asked for
     * @param sources       pins the field's GameController, keeps intruders and rivals
     * @param badPackets    counts the refused datagrams per source
     * @param stamps        the console's wall clock, for the envelopes' time stamps
     */
    public GameControllerStates(EnvelopeSink sink, MatchMode matchMode, MonitorRegistrations registrations,
                                GameControllerSources sources, BadPackets badPackets, MicrosClock stamps) {
        this.sink = sink;
        this.matchMode = matchMode;
        this.registrations = registrations;
        this.sources = sources;
        this.badPackets = badPackets;
        this.stamps = stamps;
    }

    public BadPackets badPackets() {
        return badPackets;
    }

    public GameControllerSources sources() {
        return sources;
    }

    /** This console's GameController referees from now on (one at a time). */
    public void referee(Referee own) {
        referee = own;
    }

    /** {@code own} stopped refereeing. */
    public void endRefereeing(Referee own) {
        if (referee == own) {
            referee = null;
        }
    }

    /** The state this console's own GameController sends. */
    public void own(int state) {
        if (matchMode != null) {
            matchMode.observeBelieved(state, OWN_SOURCE);
        }
    }

    /** One datagram heard on the game-state port (the listener's thread). */
    public void datagram(byte[] data, InetSocketAddress from) {
        Referee own = referee;
        if (!KnownGameStateFormats.isGameState(data)) {
            if (own != null) {
                own.otherDatagram(data, from);
            }
            return; // robots' own broadcasts on the shared port are somebody else's business
        }
        if (own != null) {
            rival(own, data, from);
        } else {
            listened(data, from);
        }
    }

    private void listened(byte[] data, InetSocketAddress from) {
        Decoded<KnownGameStateFormats.Match> r = formats.recognise(data);
        KnownGameStateFormats.Match m = r.value();
        String error = m == null ? r.failure() + ": " + r.detail()
                : m.format().isTrueData() && !registrations.isRegisteredWith(from.getAddress())
                ? "monitor true data (RGTD) from " + from.getAddress().getHostAddress()
                  + ", but this console did not register as its monitor" : null;
        String host = from.getAddress().getHostAddress();
        boolean intruder = error == null
                && sources.heard(host, from.getPort(), m.data()) == GameControllerSources.Verdict.INTRUDER;
        if (intruder) {
            error = "game state from " + host + ":" + from.getPort() + ", not the field's GameController ("
                    + sources.pinnedHost() + "): not believed";
        }
        if (error != null) {
            badPackets.count(from, error);
        }
        sink.accept(new Envelope(stamps.nowMicros(), Direction.IN, Channel.GAMECONTROLLER, from, Envelope.NO_ROBOT,
                m == null ? "gc.unknown" : m.format().kind(), null, data, error));
        if (matchMode != null && m != null && (error == null || intruder)) {
            // the strictest claim wins: an intruder saying PLAYING silences the console too (but
            // its INITIAL does not end the first listen)
            if (intruder) {
                matchMode.observe(m.data().state(), "other source at " + host + ":" + from.getPort());
            } else {
                matchMode.observeBelieved(m.data().state(), "GameController at " + host + ":" + from.getPort());
            }
        }
    }

    private void rival(Referee own, byte[] data, InetSocketAddress from) {
        if (own.ownPacket(from)) {
            return; // our own packet, heard back
        }
        Decoded<KnownGameStateFormats.Match> recognised = formats.recognise(data);
        KnownGameStateFormats.Match match = recognised.value();
        GameControlData decoded = match == null ? null : match.data();
        String kind = match == null ? "gc.unknown" : match.format().kind();
        String error = match == null ? recognised.failure() + ": " + recognised.detail() : null;
        if (error != null) {
            badPackets.count(from, error);
        }
        String key = from.getAddress().getHostAddress() + ":" + from.getPort();
        RivalGameControllers rivals = sources.others();
        long now = sources.now();
        boolean wasActive = rivals.isActive(key, now);
        rivals.heard(key, kind, decoded, now);
        sink.accept(new Envelope(stamps.nowMicros(), Direction.IN, Channel.GAMECONTROLLER, from, Envelope.NO_ROBOT, kind,
                null, data, error));
        if (matchMode != null && decoded != null) {
            matchMode.observe(decoded.state(), "GameController at " + key);
        }
        if (!wasActive) {
            String warning = rivals.warning(now);
            LOG.warn(warning);
            own.rivalHeard(warning);
        }
    }
}
