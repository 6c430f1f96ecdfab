package touchline.model;

import touchline.proto.Fumanoid;
import touchline.protocol.MessageCodec;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;
import touchline.transport.MicrosClock;
import touchline.transport.Origin;
import touchline.transport.RobotCommands;
import touchline.transport.SendResult;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The console's side of the debug-option protocol, per robot: ask a new robot for its option
 * list until one arrives, replace it when a new one comes, remember what the user switched on,
 * and reconcile: what is wanted but not streaming is requested again, and when a robot comes
 * back after being offline everything that was on is switched on again without being asked.
 * The options belong to the user, not to this process: the wanted options can be restored
 * from an earlier run ({@link #restoreWanted}), and this session only ever switches off what
 * its user wanted and then switched off ({@link #RELEASE_ATTEMPTS} tries while data still
 * comes). An option streaming for another console of the team (or switched on on the robot)
 * is never touched, so two consoles of one team do not switch each other's options off.
 * It subscribes to the live stream only: a replay's option lists and data are shown by
 * {@link #replayed()}, a {@link ShownOptions} on the replay stream, so nothing a replay plays
 * ever makes this session send (a replayed robot is not on the field, and a live robot with
 * its number must not hear about it).
 * The options chosen "in the game" (the match digest, docs/protocol.md) are reconciled the
 * same way: each option's place is sent until the robot's list confirms it, through the same
 * gate, so a choice never reaches a robot during play.
 * Over 400 lines because the wanted options, the ones being released and the match places are
 * one record per robot, reconciled against the same option list by the same tick under one lock;
 * split apart, each part would need the others' view of that list and a second lock over it.
 */
public final class DebugOptionSession implements EnvelopeSink, RobotPresence {

    static final long LIST_RETRY_MICROS = 500_000;
    static final long COMMAND_RETRY_MICROS = 1_000_000;
    static final long STREAMING_WINDOW_MICROS = 2_000_000;
    /** How often an option the user switched off is switched off while its data keeps coming. */
    static final int RELEASE_ATTEMPTS = 3;

    private final RobotCommands commands;
    private final MessageCodec codec;
    private final touchline.protocol.DebugData debugData;
    private final MicrosClock clock;
    private final ShownOptions replayed;
    private final Map<Integer, PerRobot> robots = new HashMap<>();
    private final Utf8Names names = new Utf8Names();
    private long version;

    private static final class PerRobot {
        boolean online = true;
        boolean listReceived;
        int listRequests;
        long lastListRequest = Long.MIN_VALUE / 2;
        final Map<String, Fumanoid.DebugOption> list = new LinkedHashMap<>();
        final Set<String> wanted = new LinkedHashSet<>();
        /** the options the user chose for the match digest, first = rank 1 */
        final List<String> match = new ArrayList<>();
        /** the user chose (an empty choice too): only then is the robot's digest this console's to set */
        boolean matchChosen;
        /** switched off by the user here, data still coming: off commands sent so far */
        final Map<String, Integer> releasing = new HashMap<>();
        /** when each option's data last came; updated in place (no boxed time per message) */
        final Map<String, LastData> lastData = new HashMap<>();
        final Map<String, Long> lastCommand = new HashMap<>();
        /** when each option's match rank was last sent */
        final Map<String, Long> lastRank = new HashMap<>();
        String lastHold = "";

        void dataCame(String option, long timeMicros) {
            LastData last = lastData.get(option);
            if (last == null) {
                lastData.put(option, new LastData(timeMicros));
            } else {
                last.micros = timeMicros;
            }
        }
    }

    private static final class LastData {
        long micros;

        LastData(long micros) {
            this.micros = micros;
        }
    }

    public DebugOptionSession(RobotCommands commands, MessageCodec codec, MicrosClock clock) {
        this(commands, codec, clock, clock);
    }

    /** @param replayClock the replay's position: a replayed robot's option streams by it */
    public DebugOptionSession(RobotCommands commands, MessageCodec codec, MicrosClock clock, MicrosClock replayClock) {
        this.commands = commands;
        this.codec = codec;
        this.debugData = new touchline.protocol.DebugData(codec.kinds());
        this.clock = clock;
        this.replayed = new ShownOptions(codec.kinds(), replayClock);
    }

    /** The replayed robots' options, only shown: subscribe it to the replay stream. */
    public ShownOptions replayed() {
        return replayed;
    }

    @Override
    public void accept(Envelope e) {
        if (e.direction() != Direction.IN || e.robotId() < 0 || !(e.message() instanceof Fumanoid.Message m)) {
            return;
        }
        Fumanoid.DebugOptionList list = e.extension(Fumanoid.debugOptionList);
        if (list != null) {
            onList(e.robotId(), list);
            return;
        }
        String option = optionNameOf(e, m);
        if (option != null) {
            synchronized (this) {
                robot(e.robotId()).dataCame(option, e.timeMicros());
            }
        }
    }

    /** Forgets what replayed robots showed (the replay closed); live robots are untouched. */
    public void forgetReplayed() {
        replayed.forget();
    }

    /** The {@code option} field every data message carries (teams' own types too, by convention). */
    private String optionNameOf(Envelope e, Fumanoid.Message m) {
        com.google.protobuf.Message data = debugData.dataOf(e.kind(), m);
        return data == null ? null : names.optionOf(data);
    }

    private void onList(int robotId, Fumanoid.DebugOptionList list) {
        List<String> toEnable = new ArrayList<>();
        synchronized (this) {
            PerRobot r = robot(robotId);
            r.list.clear();
            for (Fumanoid.DebugOption o : list.getOptionsList()) {
                r.list.put(o.getName(), o);
            }
            r.listReceived = true;
            for (String w : r.wanted) {
                Fumanoid.DebugOption o = r.list.get(w);
                if (o != null && !o.getEnabled()) {
                    toEnable.add(w);
                }
            }
            version++;
        }
        for (String name : toEnable) {
            command(robotId, name, true);
        }
        placeMatchItems(robotId, false);
    }

    /**
     * Chooses the options a robot puts into its match digest, in this order (first = first in
     * the digest; empty: the robot sends its Status alone in play). Remembered like the wanted
     * options and sent, held during play like every request, until the robot's list confirms it.
     */
    public SendResult setMatchItems(int robotId, List<String> options) {
        synchronized (this) {
            PerRobot r = robot(robotId);
            r.match.clear();
            r.matchChosen = true;
            for (String o : options) {
                if (!r.match.contains(o)) {
                    r.match.add(o);
                }
            }
            version++;
        }
        return placeMatchItems(robotId, true);
    }

    /** The match items of an earlier run (per robot ID), chosen again: each robot gets them when its list arrives. */
    public void restoreMatchItems(Map<Integer, List<String>> items) {
        List<Integer> now = new ArrayList<>();
        synchronized (this) {
            items.forEach((id, names) -> {
                PerRobot r = robots.get(id);
                if (r == null) {
                    r = robot(id);
                    r.online = false; // not seen yet: asked for its list when it appears
                }
                r.match.clear();
                r.match.addAll(names);
                r.matchChosen = true;
                if (r.online && r.listReceived) {
                    now.add(id);
                }
            });
            version++;
        }
        now.forEach(id -> placeMatchItems(id, true));
    }

    /** The robot's chosen match items in order (live robots). */
    public synchronized List<String> matchItems(int robotId) {
        PerRobot r = robots.get(robotId);
        return r == null ? List.of() : List.copyOf(r.match);
    }

    /** Every robot's chosen match items, to keep them with the wanted options. */
    public synchronized Map<Integer, List<String>> allMatchItems() {
        Map<Integer, List<String>> out = new java.util.TreeMap<>();
        robots.forEach((id, r) -> {
            if (r.matchChosen) {
                out.put(id, List.copyOf(r.match));
            }
        });
        return out;
    }

    /** The rank the user wants for {@code name}: 1 = first, 0 = not in the digest; the robot's own without a choice here. */
    private static int wantedRank(PerRobot r, Fumanoid.DebugOption o) {
        return r.matchChosen ? r.match.indexOf(o.getName()) + 1 : o.getMatchRank();
    }

    /**
     * Sends the place of each listed option whose rank the robot's list does not show yet
     * ({@code force}: also those asked within the retry time); the last result, or "nothing to
     * send" when the list already agrees or has not come.
     */
    private SendResult placeMatchItems(int robotId, boolean force) {
        Map<String, int[]> toSend = new LinkedHashMap<>();
        long now = clock.nowMicros();
        synchronized (this) {
            PerRobot r = robot(robotId);
            if (!r.matchChosen) {
                // another console's choice (or the robot's own) is never touched
                return new SendResult(SendResult.Outcome.SENT, "no match items chosen here");
            }
            if (!r.online || !r.listReceived) {
                return SendResult.held("the option list of robot " + robotId + " has not come yet; sent when it does");
            }
            for (Fumanoid.DebugOption o : r.list.values()) {
                int rank = wantedRank(r, o);
                long last = r.lastRank.getOrDefault(o.getName(), Long.MIN_VALUE / 2);
                if (o.getMatchRank() != rank && (force || now - last >= COMMAND_RETRY_MICROS)) {
                    boolean enable = o.getEnabled() || r.wanted.contains(o.getName());
                    toSend.put(o.getName(), new int[]{enable ? 1 : 0, rank});
                }
            }
        }
        SendResult last = new SendResult(SendResult.Outcome.SENT, "the robot's list already shows this choice");
        for (Map.Entry<String, int[]> e : toSend.entrySet()) {
            last = commands.send(robotId, codec.optionRequest(e.getKey(), e.getValue()[0] == 1, e.getValue()[1]));
            synchronized (this) {
                PerRobot r = robot(robotId);
                r.lastRank.put(e.getKey(), clock.nowMicros());
                r.lastHold = last.isSent() ? "" : last.reason();
                version++;
            }
        }
        return last;
    }

    @Override
    public void cameOnline(int robotId, boolean firstTime) {
        List<String> reEnable;
        synchronized (this) {
            PerRobot r = robot(robotId);
            r.online = true;
            r.listReceived = r.listReceived && firstTime;
            reEnable = firstTime ? List.of() : List.copyOf(r.wanted);
            version++;
        }
        requestList(robotId);
        for (String name : reEnable) {
            command(robotId, name, true);
        }
    }

    @Override
    public void wentOffline(int robotId) {
        synchronized (this) {
            PerRobot r = robot(robotId);
            r.online = false;
            r.listReceived = false;
            version++;
        }
    }

    /**
     * Switches an option on or off for a robot; remembered, so it survives the robot's restarts.
     * Off is sent only for an option this console wanted: one it never switched on (another
     * console's, or the robot's own) is left as it is, and the result says so.
     */
    public SendResult setWanted(int robotId, String option, boolean on) {
        synchronized (this) {
            PerRobot r = robot(robotId);
            if (on) {
                r.wanted.add(option);
                r.releasing.remove(option);
            } else if (r.wanted.remove(option)) {
                r.releasing.put(option, 1);
            } else {
                return SendResult.failed(option + " was not switched on by this console; left as it is");
            }
            version++;
        }
        return command(robotId, option, on);
    }

    /**
     * Switches an option off because the user named it (the {@code options --off} command),
     * whoever switched it on: an explicit request, unlike the reconciliation, which never
     * touches what this console did not switch on. Tried {@link #RELEASE_ATTEMPTS} times at most.
     */
    public SendResult switchOff(int robotId, String option) {
        synchronized (this) {
            PerRobot r = robot(robotId);
            r.wanted.remove(option);
            r.releasing.put(option, 1);
            version++;
        }
        return command(robotId, option, false);
    }

    /**
     * The wanted options of an earlier run (per robot ID), wanted again: each robot gets them
     * when it appears (or at once, when it is already here and its list arrived).
     */
    public void restoreWanted(Map<Integer, Set<String>> wanted) {
        Map<Integer, List<String>> now = new HashMap<>();
        synchronized (this) {
            wanted.forEach((id, names) -> {
                PerRobot r = robots.get(id);
                if (r == null) {
                    r = robot(id);
                    r.online = false; // not seen yet: asked for its list when it appears
                }
                for (String name : names) {
                    if (r.wanted.add(name) && r.online && r.listReceived && r.list.containsKey(name)) {
                        now.computeIfAbsent(id, k -> new ArrayList<>()).add(name);
                    }
                }
            });
            version++;
        }
        now.forEach((id, names) -> names.forEach(name -> command(id, name, true)));
    }

    /** Every robot's wanted options (live robots only), to keep them for the next run. */
    public synchronized Map<Integer, Set<String>> allWanted() {
        Map<Integer, Set<String>> out = new java.util.TreeMap<>();
        robots.forEach((id, r) -> {
            if (!r.wanted.isEmpty()) {
                out.put(id, Set.copyOf(r.wanted));
            }
        });
        return out;
    }

    /** Retries what has not taken effect yet; call a few times a second. */
    public void tick() {
        long now = clock.nowMicros();
        List<Integer> needList = new ArrayList<>();
        Map<Integer, Map<String, Boolean>> retries = new HashMap<>();
        synchronized (this) {
            for (Map.Entry<Integer, PerRobot> e : robots.entrySet()) {
                PerRobot r = e.getValue();
                if (!r.online) {
                    continue;
                }
                if (!r.listReceived && now - r.lastListRequest >= LIST_RETRY_MICROS) {
                    needList.add(e.getKey());
                }
                if (!r.listReceived) {
                    continue;
                }
                if (!r.lastHold.isEmpty() && nothingWaits(r, now)) {
                    r.lastHold = ""; // e.g. the options stream again after play: the note would go stale
                    version++;
                }
                for (String name : r.list.keySet()) {
                    boolean wanted = r.wanted.contains(name);
                    boolean streaming = streaming(r, name, now);
                    long last = r.lastCommand.getOrDefault(name, Long.MIN_VALUE / 2);
                    if (now - last < COMMAND_RETRY_MICROS) {
                        continue;
                    }
                    if (wanted && !streaming) {
                        retries.computeIfAbsent(e.getKey(), k -> new LinkedHashMap<>()).put(name, true);
                    } else if (!wanted && r.releasing.containsKey(name)) {
                        // only what this console switched off; another console's option is never touched
                        int sent = r.releasing.get(name);
                        if (!streaming || sent >= RELEASE_ATTEMPTS) {
                            r.releasing.remove(name);
                        } else {
                            r.releasing.put(name, sent + 1);
                            retries.computeIfAbsent(e.getKey(), k -> new LinkedHashMap<>()).put(name, false);
                        }
                    }
                }
            }
        }
        needList.forEach(this::requestList);
        retries.forEach((id, options) -> options.forEach((name, on) -> command(id, name, on)));
        List<Integer> listed = new ArrayList<>();
        synchronized (this) {
            robots.forEach((id, r) -> {
                if (r.online && r.listReceived) {
                    listed.add(id);
                }
            });
        }
        listed.forEach(id -> placeMatchItems(id, false));
    }

    /** Whether every wanted option of the robot streams and none it switched off is still being released. */
    private boolean nothingWaits(PerRobot r, long now) {
        if (!r.releasing.isEmpty()) {
            return false;
        }
        for (String name : r.wanted) {
            if (r.list.containsKey(name) && !streaming(r, name, now)) {
                return false;
            }
        }
        return true;
    }

    private boolean streaming(PerRobot r, String name, long now) {
        LastData t = r.lastData.get(name);
        return t != null && now - t.micros <= STREAMING_WINDOW_MICROS;
    }

    private void requestList(int robotId) {
        // noted before sending: the tick on its own thread must not send a second request while
        // this one is on its way (publishing it to the bus takes a while on a busy machine)
        synchronized (this) {
            robot(robotId).lastListRequest = clock.nowMicros();
        }
        SendResult result = commands.send(robotId, codec.optionListRequest());
        synchronized (this) {
            PerRobot r = robot(robotId);
            r.listRequests++;
            r.lastHold = result.isSent() ? "" : result.reason();
            version++;
        }
    }

    private SendResult command(int robotId, String option, boolean on) {
        SendResult result = commands.send(robotId, codec.optionRequest(option, on));
        synchronized (this) {
            PerRobot r = robot(robotId);
            r.lastCommand.put(option, clock.nowMicros());
            r.lastHold = result.isSent() ? "" : result.reason();
            version++;
        }
        return result;
    }

    private PerRobot robot(int id) {
        return robots.computeIfAbsent(id, k -> new PerRobot());
    }

    /** The live robot's options. */
    public RobotOptions options(int robotId) {
        return options(robotId, Origin.LIVE);
    }

    /** A live or replayed robot's options (a replayed robot's are only shown: nobody can switch them). */
    public synchronized RobotOptions options(int robotId, Origin origin) {
        if (origin == Origin.REPLAY) {
            return replayed.options(robotId);
        }
        PerRobot r = robots.get(robotId);
        if (r == null) {
            return new RobotOptions(robotId, false, 0, List.of(), "");
        }
        long now = clock.nowMicros();
        List<OptionState> states = new ArrayList<>();
        for (Fumanoid.DebugOption o : r.list.values()) {
            states.add(new OptionState(o.getName(), o.getDescription(), o.getKind(), r.wanted.contains(o.getName()),
                    o.getEnabled(), streaming(r, o.getName(), now), wantedRank(r, o), o.getMatchRank()));
        }
        return new RobotOptions(robotId, r.listReceived, r.listRequests, states, r.lastHold);
    }

    public synchronized Set<String> wanted(int robotId) {
        PerRobot r = robots.get(robotId);
        return r == null ? Set.of() : Set.copyOf(r.wanted);
    }

    /** Grows with every change of the live robots' options or the replayed ones' lists. */
    public long version() {
        long own;
        synchronized (this) {
            own = version;
        }
        return own + replayed.version();
    }
}
