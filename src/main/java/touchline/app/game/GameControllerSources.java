package touchline.app.game;

import touchline.game.GameClock;

import touchline.protocol.gamecontroller.GameControlData;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;

/**
 * Which GameController the console believes. The GameController protocol has no
 * authentication, so anyone on the field network can send game states; this pins one source
 * and watches it (docs/security.md, "GameController spoofing"):
 * <ul>
 *   <li><b>Pinning.</b> The field's GameController is the first host heard, or the host the
 *   user gave ({@code --gc-address}); pinned by IP address, any port, so a restarted
 *   GameController on the same machine stays pinned. Every other source that sends game states
 *   is an <em>intruder</em>: shown as a warning with its address and packet count while heard
 *   within {@link #ACTIVE_MS}, and never believed (its packets do not drive the model's game
 *   state). Match mode still hears it: a claim of play from anyone keeps the console silent.</li>
 *   <li><b>Packet numbers</b> of the pinned source (0–255, wrapping): one ahead is normal; a
 *   step forward by up to 128 counts the packets lost between; the same number again is counted
 *   as a repeat; a step back is <em>suspicious</em> (a second sender with the pinned address)
 *   unless it looks like a GameController restart: the new number is below
 *   {@link #RESTART_BELOW} and the state is INITIAL. After {@link #SILENCE_MS} of silence any
 *   number starts a fresh sequence.</li>
 *   <li><b>Impossible jumps</b> between consecutive packets of the pinned source: a score up or
 *   down by more than one (one down is a referee's correction); the state going back to INITIAL
 *   from READY, SET or PLAYING; INITIAL straight to PLAYING or FINISHED; FINISHED from PLAYING
 *   while the half's clock still showed more than {@link #EARLY_FINISH_SECONDS} s.</li>
 * </ul>
 * Flags are counted and kept (the last {@link #LOG_SIZE}) for the views; they never act on
 * anything by themselves. Thread-safe; the clock is injected.
 */
public final class GameControllerSources {

    /** An intruder heard within this long is shown as a warning (the one window of {@link RivalGameControllers}). */
    public static final long ACTIVE_MS = RivalGameControllers.ACTIVE_MS;
    /** After this long without a packet from the pinned source, packet numbers start afresh. */
    public static final long SILENCE_MS = 5000;
    /** A packet number below this with state INITIAL after a step back is a GameController restart. */
    public static final int RESTART_BELOW = 8;
    /** FINISHED from PLAYING with more than this many seconds on the clock is flagged. */
    public static final int EARLY_FINISH_SECONDS = 10;
    /** Flags kept for the views. */
    public static final int LOG_SIZE = 50;

    /** What was decided about one packet. */
    public enum Verdict {
        /** From the pinned GameController (possibly just pinned): believe it. */
        PINNED,
        /** From another source: show it as a warning, do not believe it. */
        INTRUDER
    }

    /**
     * Another source that sent game states.
     *
     * @param source    "address:port"
     * @param packets   game states heard from it
     * @param lastState the last state it claimed
     * @param atMs      when it was last heard
     */
    public record Intruder(String source, long packets, int lastState, long atMs) {
    }

    /**
     * One flagged observation about the pinned source.
     *
     * @param atMs clock time
     * @param text what was seen, in words
     */
    public record Flag(long atMs, String text) {
    }

    private final GameClock clock;
    private final String givenHost;
    private String pinnedHost;
    private String pinnedHow = "";
    private GameControlData last;
    private long lastAtMs;
    private long packets;
    private long lost;
    private long repeats;
    private long restarts;
    private long suspicious;
    /** Other sources: intruders while this console listens, rivals while it referees. */
    private final RivalGameControllers intruders = new RivalGameControllers();
    private final Deque<Flag> flags = new ArrayDeque<>();
    private Flag lastSuspicious;

    /**
     * @param clock     milliseconds, monotonic
     * @param givenHost the address the user gave ({@code --gc-address}), or null to pin the first heard
     */
    public GameControllerSources(GameClock clock, String givenHost) {
        this.clock = clock;
        this.givenHost = givenHost == null || givenHost.isBlank() ? null : givenHost.strip();
        this.pinnedHost = this.givenHost;
        this.pinnedHow = this.givenHost == null ? "" : "given";
    }

    /**
     * Judges one decoded game state.
     *
     * @param host the sender's IP address (e.g. "10.0.0.2")
     * @param port the sender's UDP port
     */
    public synchronized Verdict heard(String host, int port, GameControlData data) {
        long now = clock.millis();
        if (pinnedHost == null) {
            pinnedHost = host;
            pinnedHow = "first heard";
        }
        if (!pinnedHost.equals(host)) {
            String source = host + ":" + port;
            intruders.heard(source, "game state", data, now);
            return Verdict.INTRUDER;
        }
        packets++;
        if (last != null && now - lastAtMs <= SILENCE_MS) {
            checkSequence(data, now);
        }
        last = data;
        lastAtMs = now;
        return Verdict.PINNED;
    }

    private void checkSequence(GameControlData data, long now) {
        int step = (data.packetNumber() - last.packetNumber()) & 0xFF;
        if (step == 0) {
            repeats++;
        } else if (step > 128) {
            if (data.packetNumber() < RESTART_BELOW && data.state() == GameControlData.STATE_INITIAL) {
                restarts++;
                flag(now, "the GameController restarted (packet number " + last.packetNumber() + " → "
                        + data.packetNumber() + ", INITIAL)", false);
                return; // a new game: nothing to compare with
            }
            flag(now, "packet number went back from " + last.packetNumber() + " to " + data.packetNumber()
                    + ": a second sender using the GameController's address?", true);
        } else if (step > 1) {
            lost += step - 1;
        }
        checkJumps(data, now);
    }

    private void checkJumps(GameControlData data, long now) {
        for (int i = 0; i < 2; i++) {
            int before = last.teams().get(i).score();
            int after = data.teams().get(i).score();
            if (after - before > 1 || before - after > 1) {
                flag(now, "team " + data.teams().get(i).teamNumber() + "'s score jumped from " + before + " to "
                        + after, true);
            }
        }
        int from = last.state();
        int to = data.state();
        String change = GameControlData.stateName(from) + " → " + GameControlData.stateName(to);
        boolean play = GameControlData.isPlay(from);
        if (to == GameControlData.STATE_INITIAL && play) {
            flag(now, "state went back: " + change, true);
        } else if (from == GameControlData.STATE_INITIAL
                && (to == GameControlData.STATE_PLAYING || to == GameControlData.STATE_FINISHED)) {
            flag(now, "state skipped READY and SET: " + change, true);
        } else if (from == GameControlData.STATE_PLAYING && to == GameControlData.STATE_FINISHED
                && last.secsRemaining() > EARLY_FINISH_SECONDS) {
            flag(now, "FINISHED with " + last.secsRemaining() + " s still on the clock", true);
        }
    }

    private void flag(long now, String text, boolean isSuspicious) {
        Flag f = new Flag(now, text);
        if (isSuspicious) {
            suspicious++;
            lastSuspicious = f;
        }
        flags.addLast(f);
        while (flags.size() > LOG_SIZE) {
            flags.removeFirst();
        }
    }

    /**
     * The one tracker of other GameControllers (intruders; rivals while this console referees,
     * {@link GameControllerStates}).
     */
    public RivalGameControllers others() {
        return intruders;
    }

    /** This tracker's clock (milliseconds, monotonic). */
    public long now() {
        return clock.millis();
    }

    private static Intruder intruder(String source, RivalGameControllers.Rival r) {
        return new Intruder(source, r.count(), r.state(), r.atMs());
    }

    /** The pinned host, or "" before any GameController was heard (and none was given). */
    public synchronized String pinnedHost() {
        return pinnedHost == null ? "" : pinnedHost;
    }

    /** Intruders heard within {@link #ACTIVE_MS}, by source. */
    public synchronized List<Intruder> activeIntruders() {
        long now = clock.millis();
        List<Intruder> out = new ArrayList<>();
        intruders.active(now).forEach((source, r) -> out.add(intruder(source, r)));
        return out;
    }

    /**
     * Every intruder heard, by source; the {@link RecentSources#CAPACITY} heard last when more
     * sent (the others are counted in {@link #forgottenIntruders}).
     */
    public synchronized List<Intruder> allIntruders() {
        List<Intruder> out = new ArrayList<>();
        intruders.all().forEach((source, r) -> out.add(intruder(source, r)));
        return out;
    }

    /** Intruder sources forgotten because more than {@link RecentSources#CAPACITY} sent game states. */
    public synchronized long forgottenIntruders() {
        return intruders.forgotten();
    }

    /** Flagged observations, oldest first (the last {@link #LOG_SIZE}). */
    public synchronized List<Flag> flags() {
        return List.copyOf(flags);
    }

    public synchronized long packets() {
        return packets;
    }

    /** Packets of the pinned source that never arrived (gaps in the packet numbers). */
    public synchronized long lost() {
        return lost;
    }

    public synchronized long repeats() {
        return repeats;
    }

    public synchronized long restarts() {
        return restarts;
    }

    /** Suspicious observations: packet numbers going back, impossible jumps. */
    public synchronized long suspicious() {
        return suspicious;
    }

    /**
     * The warning to show (status bar, GameController view, {@code listen}), in words; "" when no
     * other source sent game states within {@link #ACTIVE_MS} and nothing suspicious was seen
     * within that time.
     */
    public synchronized String warning() {
        long now = clock.millis();
        StringBuilder b = new StringBuilder();
        List<Intruder> active = activeIntruders();
        if (!active.isEmpty()) {
            b.append("WARNING: another source is sending game states: ");
            for (int i = 0; i < active.size(); i++) {
                Intruder in = active.get(i);
                b.append(i == 0 ? "" : ", ").append(in.source).append(" (").append(in.packets)
                        .append(in.packets == 1 ? " packet" : " packets").append(", last ")
                        .append(GameControlData.stateName(in.lastState)).append(')');
            }
            b.append(" — not believed; the GameController is ").append(pinnedHost).append(" (").append(pinnedHow)
                    .append(')');
        }
        if (lastSuspicious != null && now - lastSuspicious.atMs <= ACTIVE_MS) {
            b.append(b.isEmpty() ? "" : "; ").append("SUSPICIOUS GameController packets (").append(suspicious)
                    .append("): ").append(lastSuspicious.text);
        }
        return b.toString();
    }

    /** One line for {@code listen}: the pinned source and its counters. */
    public synchronized String describe() {
        if (pinnedHost == null) {
            return "GameController: none heard yet";
        }
        return "GameController " + pinnedHost + " (" + pinnedHow + "): " + packets + " packets, " + lost + " lost, "
                + repeats + " repeated, " + restarts + " restarts, " + suspicious + " suspicious"
                + (intruders.forgotten() == 0 ? "" : ", " + intruders.forgotten() + " other sources forgotten (more than "
                + intruders.capacity() + " sent game states)");
    }
}
