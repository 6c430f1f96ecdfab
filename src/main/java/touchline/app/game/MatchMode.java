package touchline.app.game;

import touchline.game.GameClock;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import touchline.protocol.gamecontroller.GameControlData;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Consumer;

/**
 * The tournament rule "during play only the GameController talks to the robots": while any
 * game state heard on the network (or sent by our own GameController) within the last
 * {@link #STALE_MS} ms is READY, SET or PLAYING, or any source at all claimed READY, SET or
 * PLAYING within the last {@link #PLAY_MEMORY_MS} ms (the strictest claim wins: a forged
 * FINISHED or INITIAL, from another source or with the GameController's own address, never
 * releases the console while a GameController keeps saying PLAYING), {@link #mayConsoleSend()} is false and the
 * console's outbound path must hold back debug requests, reliable-stream data and NAO
 * commands (reporting each with {@link #hold}). When play stops, listeners hear
 * {@code true} and held-back requests may resume. The referee-approved exception is an
 * explicit override, which is logged with its reason.
 */
public final class MatchMode {

    /** A source not heard for this long no longer counts (a GameController sends every 500 ms). */
    public static final long STALE_MS = 5000;
    /**
     * A claim of READY, SET or PLAYING from any source keeps match mode on for this long, whatever
     * is heard after it: four GameController intervals, so three lost packets in a row do not
     * let a forged FINISHED through. The price: a true FINISHED releases the console 2 s late.
     */
    public static final long PLAY_MEMORY_MS = 2000;
    /** Every GameController format (HL, SPL, HSL) is sent twice a second. */
    public static final long GAMECONTROLLER_INTERVAL_MS = 500;
    /**
     * How long a console that starts listening to the field holds robot traffic back: 2.5
     * GameController intervals, so a console started in the middle of a game on a network that
     * loses one packet in two (PLAYING heard once a second) hears the GameController before it
     * says anything to a robot. A non-play state from a believed GameController ends it early.
     */
    public static final long LISTEN_FIRST_MS = GAMECONTROLLER_INTERVAL_MS * 5 / 2;
    /** How many held-back request descriptions are kept for the notice. */
    public static final int HELD_LOG = 100;

    private static final Logger LOG = LoggerFactory.getLogger(MatchMode.class);
    /** Why the console is silent in its first moments, before any GameController was heard. */
    private static final String LISTENING = "listening for a GameController before talking to robots";

    /** A state heard from a source; {@code reported} when a robot repeats what it heard from a GameController. */
    private record Heard(int state, long atMs, boolean reported) {
    }

    /**
     * One use of the override switch.
     *
     * @param atMs   clock time
     * @param on     switched on or off
     * @param reason what the operator gave as the reason
     */
    public record OverrideEntry(long atMs, boolean on, String reason) {
    }

    private final GameClock clock;
    // bounded: a new source beyond the capacity forgets the one heard longest ago. A flood of
    // made-up sources can push the GameController's PLAYING out of `heard`, never out of
    // `lastPlayClaim` unless it claims play itself, so forgetting never lifts the silence.
    private final RecentSources<Heard> heard = new RecentSources<>();
    private final RecentSources<Heard> lastPlayClaim = new RecentSources<>();
    private final Deque<String> held = new ArrayDeque<>();
    private final List<OverrideEntry> overrideLog = new ArrayList<>();
    private final List<Consumer<Boolean>> listeners = new CopyOnWriteArrayList<>();
    private long heldCount;
    private long heldSincePlay;
    private boolean override;
    private boolean lastMaySend = true;
    private long listeningUntilMs = Long.MIN_VALUE;
    /** When a believed GameController last said a state that is not play: robots' earlier reports of play are stale. */
    private long believedStopAtMs = Long.MIN_VALUE;
    /** How often the console's may-send changed: a window that idles wakes on it. */
    private long changes;
    private long listenMs;
    /** What ended the first listen early (a non-play state heard), else null. */
    private String listenEndedBy;
    /** Why the first listen ended, once it has; null before. */
    private String listenOutcome;
    private final List<Consumer<String>> listenEndListeners = new CopyOnWriteArrayList<>();

    public MatchMode(GameClock clock) {
        this.clock = clock;
    }

    /**
     * Called with {@code true} when the console may send again (flush what was held back),
     * {@code false} when it must stop. Runs on the thread that noticed the change (often the
     * GameController sender or receiver), so it must not block.
     */
    public void addListener(Consumer<Boolean> onMayConsoleSendChanged) {
        listeners.add(onMayConsoleSendChanged);
    }

    /**
     * Holds robot traffic back for {@code ms} from now while the console first listens for a
     * GameController (the port watch just opened); a PLAYING heard meanwhile keeps it silent.
     */
    public void listenFirst(long ms) {
        synchronized (this) {
            listeningUntilMs = clock.millis() + ms;
            listenMs = ms;
            listenEndedBy = null;
            listenOutcome = null;
        }
        refresh();
    }

    /**
     * Calls {@code onEnd} once with why the first listen ended ("heard INITIAL (GameController
     * at …): talking to robots", "no GameController heard in 1250 ms: …", or play
     * heard): at once when it has already ended, else on the thread that notices the end.
     */
    public void onListenEnd(Consumer<String> onEnd) {
        String outcome;
        synchronized (this) {
            outcome = listenOutcome;
            if (outcome == null) {
                listenEndListeners.add(onEnd);
            }
        }
        if (outcome != null) {
            onEnd.accept(outcome);
        }
    }

    /**
     * Records a game state from a GameController the console believes (the pinned one, its own,
     * the remote console's): as {@link #observe}, and a state that is not play ends the first
     * listen at once, since that GameController is heard and says play is off.
     */
    public void observeBelieved(int gameState, String source) {
        synchronized (this) {
            if (!GameControlData.isPlay(gameState)) {
                believedStopAtMs = clock.millis();
            }
            if (!GameControlData.isPlay(gameState) && listening()) {
                listeningUntilMs = clock.millis();
                listenEndedBy = "heard " + GameControlData.stateName(gameState) + " (" + source + ")";
            }
        }
        observe(gameState, source);
    }

    /** Records a game state byte (0 INITIAL ... 4 FINISHED) heard from, or sent by, {@code source}. */
    public void observe(int gameState, String source) {
        observe(gameState, source, false);
    }

    /**
     * Records the game state a robot reports (what it last heard from a GameController). It keeps
     * match mode on like any claim, but a GameController heard at the same time is named first: the
     * robot only repeats it. A report of play made before a believed GameController said a state
     * that is not play no longer counts: the robot repeated what that GameController has since ended
     * (a robot switched off after the final whistle kept the console silent for 5 s).
     */
    public void observeReported(int gameState, int robot) {
        observe(gameState, "robot " + robot, true);
    }

    private void observe(int gameState, String source, boolean reported) {
        synchronized (this) {
            Heard h = new Heard(gameState, clock.millis(), reported);
            heard.put(source, h);
            if (GameControlData.isPlay(gameState)) {
                lastPlayClaim.put(source, h);
            }
        }
        refresh();
    }

    public boolean mayConsoleSend() {
        refresh();
        synchronized (this) {
            return lastMaySend;
        }
    }

    /** Whether play is on according to the network (regardless of the override). */
    public synchronized boolean playIsOn() {
        return playingSource() != null;
    }

    /**
     * Reports a console request the outbound path wants to send.
     *
     * @return true when it must be held back (match mode active, no override)
     */
    public boolean hold(String what) {
        if (mayConsoleSend()) {
            return false;
        }
        synchronized (this) {
            heldCount++;
            heldSincePlay++;
            held.addLast(what);
            while (held.size() > HELD_LOG) {
                held.removeFirst();
            }
        }
        return true;
    }

    /** Requests held back since play last stopped, oldest first. */
    public synchronized List<String> heldBack() {
        return List.copyOf(held);
    }

    public synchronized long heldCount() {
        return heldCount;
    }

    /** Switches the override on or off; every switch is logged with its reason. */
    public void setOverride(boolean on, String reason) {
        synchronized (this) {
            override = on;
            overrideLog.add(new OverrideEntry(clock.millis(), on, reason == null ? "" : reason));
        }
        LOG.warn("match mode override {} by operator: {}", on ? "ON" : "off", reason);
        refresh();
    }

    public synchronized boolean isOverridden() {
        return override;
    }

    public synchronized List<OverrideEntry> overrideLog() {
        return List.copyOf(overrideLog);
    }

    /** The text to show, or "" when match mode is not holding anything back. */
    public String notice() {
        String play = play();
        if (play.isEmpty()) {
            return "";
        }
        synchronized (this) {
            if (override) {
                return "MATCH MODE OVERRIDDEN: " + play + " but the console may send";
            }
            return "Match mode: " + play + ", console silent except GameController; " + heldSincePlay
                    + (heldSincePlay == 1 ? " send attempt" : " send attempts")
                    + " held back since play began (retries included)";
        }
    }

    /** Why match mode is on in words, e.g. "game is PLAYING (GameController at 10.0.0.2:3838)"; "" when play is off. */
    public String play() {
        refresh();
        synchronized (this) {
            String source = playingSource();
            if (source == null) {
                return override || !listening() ? "" : LISTENING + " (" + (listeningUntilMs - clock.millis())
                        + " ms more; a GameController losing one packet in two is heard within " + listenMs + " ms)";
            }
            Heard now = heard.get(source);
            if (now == null) { // forgotten in a flood of other sources; its claim of play is kept
                return "game was " + GameControlData.stateName(lastPlayClaim.get(source).state) + " (" + source
                        + "); silent until " + PLAY_MEMORY_MS + " ms after play";
            }
            if (GameControlData.isPlay(now.state) && now.reported && !gameControllerHeard()) {
                return "game is " + GameControlData.stateName(now.state) + " (" + source + " reports it; no "
                        + "GameController heard for " + STALE_MS / 1000 + " s: the robots repeat the last state they "
                        + "heard; start a GameController and finish the game, or override match mode with a reason)";
            }
            if (GameControlData.isPlay(now.state)) {
                return "game is " + GameControlData.stateName(now.state) + " (" + source + ")";
            }
            return "game was " + GameControlData.stateName(lastPlayClaim.get(source).state) + " " + (clock.millis()
                    - lastPlayClaim.get(source).atMs) + " ms ago (" + source + "), now says "
                    + GameControlData.stateName(now.state) + "; silent until " + PLAY_MEMORY_MS + " ms after play";
        }
    }

    /** Re-evaluates (sources go stale with time) and notifies listeners of a change. */
    public void refresh() {
        boolean now;
        boolean changed;
        String why;
        String listenEnd = null;
        List<Consumer<String>> toTell = List.of();
        synchronized (this) {
            String source = playingSource();
            if (listenOutcome == null && listenMs > 0 && (source != null || !listening())) {
                listenOutcome = source != null ? "a game in play (" + source + "): silent while it lasts"
                        : (listenEndedBy != null ? listenEndedBy : "no GameController heard in " + listenMs + " ms")
                        + ": talking to robots";
                listenEnd = listenOutcome;
                toTell = List.copyOf(listenEndListeners);
                listenEndListeners.clear();
            }
            now = override || source == null && !listening();
            changed = now != lastMaySend;
            lastMaySend = now;
            if (changed && !now) {
                heldSincePlay = 0;
            }
            if (changed && now) {
                held.clear();
            }
            if (changed) {
                changes++;
            }
            why = !changed ? null : now ? "may send again"
                    : source != null ? "silent: a game in play (" + source + ")" : "silent: " + LISTENING;
        }
        if (changed) {
            LOG.info("match mode: console {}", why);
            for (Consumer<Boolean> l : listeners) {
                l.accept(now);
            }
        }
        for (Consumer<String> l : toTell) {
            l.accept(listenEnd);
        }
    }

    private boolean listening() {
        return clock.millis() < listeningUntilMs;
    }

    /**
     * A count that moves each time the console's may-send changes, after re-evaluating what went
     * stale: play ends by the clock with nothing else heard, and an idle window must still show it.
     */
    public long changes() {
        refresh();
        synchronized (this) {
            return changes;
        }
    }

    /** A robot's report of play that a believed GameController's later non-play state has ended. */
    private boolean superseded(Heard h) {
        return h.reported && h.atMs <= believedStopAtMs;
    }

    /**
     * Whether robot traffic is held only because the console still listens for a GameController
     * after it started ({@link #listenFirst}): a one-shot command waits this out rather than
     * report its request held.
     */
    public synchronized boolean listeningFirst() {
        return listening() && !override && playingSource() == null;
    }

    /** Whether a source other than a robot's report was heard within {@link #STALE_MS}. */
    private boolean gameControllerHeard() {
        long now = clock.millis();
        return heard.values().stream().anyMatch(h -> !h.reported && now - h.atMs <= STALE_MS);
    }

    /**
     * The source whose claim of play keeps match mode on, or null: a GameController before the
     * robots that repeat it, then the most recent claim of play.
     */
    private String playingSource() {
        long now = clock.millis();
        String reported = null;
        for (Map.Entry<String, Heard> e : heard.entries()) {
            Heard h = e.getValue();
            if (now - h.atMs <= STALE_MS && GameControlData.isPlay(h.state) && !superseded(h)) {
                if (!h.reported) {
                    return e.getKey();
                }
                reported = reported == null ? e.getKey() : reported;
            }
        }
        if (reported != null) {
            return reported;
        }
        for (Map.Entry<String, Heard> e : lastPlayClaim.entries()) {
            if (now - e.getValue().atMs <= PLAY_MEMORY_MS && !superseded(e.getValue())) {
                return e.getKey();
            }
        }
        return null;
    }
}
