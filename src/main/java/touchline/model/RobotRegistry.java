package touchline.model;

import touchline.security.Authenticity;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.MicrosClock;
import touchline.transport.Origin;

import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * Every robot ever seen (one packet is enough), online while its keep-alives arrive, with
 * per-robot counters; and every sender address with its malformed datagrams. One side per
 * stream: {@link #live()} is subscribed to the live stream, {@link #replay()} to the replay
 * stream, each fed on its stream's thread; views and commands read both from any thread.
 * So robot 3 of a recording is not robot 3 on the field: it is online by the replay's clock,
 * and never tells the presence listeners (which talk to live robots) anything.
 */
public final class RobotRegistry {

    /**
     * Keep-alives come every 200 ms in the lab but only once a second during a game (the HSL
     * 2026 rules allow a robot one debug packet per second; the firmware keeps to it in
     * READY/SET/PLAYING), so a robot is offline after three missed game-rate keep-alives. With
     * 1 s, every robot flickered offline during play.
     */
    public static final long DEFAULT_OFFLINE_AFTER_MICROS = 3_000_000;
    private static final int MAX_NOTES = 200;

    private final MicrosClock clock;
    private final MicrosClock replayClock;
    private final long offlineAfterMicros;
    private final Side live;
    private final Side replay;
    private final Map<Integer, Robot> robots;
    private final Map<Integer, Robot> replayed;
    private final List<RobotPresence> presence = new CopyOnWriteArrayList<>();
    private final List<String> notes = new ArrayList<>();
    private long version;
    private volatile RosReadings rosReadings = new RosReadings();

    private static final class Source {
        long packets;
        long malformed;
        String lastError = "";
        long lastSeen;
    }

    public RobotRegistry(MicrosClock clock) {
        this(clock, DEFAULT_OFFLINE_AFTER_MICROS);
    }

    public RobotRegistry(MicrosClock clock, long offlineAfterMicros) {
        this(clock, clock, offlineAfterMicros);
    }

    /** @param replayClock the replay's position: replayed robots are online by it */
    public RobotRegistry(MicrosClock clock, MicrosClock replayClock, long offlineAfterMicros) {
        this.clock = clock;
        this.replayClock = replayClock;
        this.offlineAfterMicros = offlineAfterMicros;
        this.live = new Side(true);
        this.replay = new Side(false);
        this.robots = live.robots;
        this.replayed = replay.robots;
    }

    /** The live robots' side: subscribe it to the live stream. */
    public touchline.transport.EnvelopeSink live() {
        return live;
    }

    /** The replayed robots' side: subscribe it to the replay stream. */
    public touchline.transport.EnvelopeSink replay() {
        return replay;
    }

    public void addPresenceListener(RobotPresence listener) {
        presence.add(listener);
    }

    /** The robots and senders of one stream; the registry's lock guards both sides. */
    private final class Side implements touchline.transport.EnvelopeSink {
        final Map<Integer, Robot> robots = new TreeMap<>();
        final Map<InetSocketAddress, Source> sources = new LinkedHashMap<>();
        /** Only live robots coming online are told to the presence listeners. */
        private final boolean tellsPresence;

        Side(boolean tellsPresence) {
            this.tellsPresence = tellsPresence;
        }

        @Override
        public void accept(Envelope e) {
            if (e.direction() != Direction.IN) {
                return;
            }
            int cameOnline = Envelope.NO_ROBOT;
            boolean first = false;
            synchronized (RobotRegistry.this) {
                Source source = null;
                if (e.peer() != null) {
                    source = sources.computeIfAbsent(e.peer(), a -> new Source());
                    source.packets++;
                    source.lastSeen = e.timeMicros();
                }
                if (e.isMalformed() && source != null) {
                    source.malformed++;
                    source.lastError = e.error();
                    attributeMalformed(e.peer(), robots);
                }
                if (e.authenticity() == Authenticity.FORGED && e.robotId() >= 0 && e.robotId() <= 255) {
                    // shown on the robot it claims to be (ids beyond one byte are no robot's), never taken as its data
                    Robot claimed = robots.computeIfAbsent(e.robotId(), id -> new Robot(id, e.origin(), e.timeMicros()));
                    if (claimed.forgery(e)) {
                        note(claimed.forged + " forged datagram(s) claiming robot " + e.robotId() + "; last from "
                                + claimed.lastForgery);
                    }
                }
                if (e.robotId() >= 0 && !e.isMalformed()) {
                    Robot robot = robots.get(e.robotId());
                    if (robot == null) {
                        robot = new Robot(e.robotId(), e.origin(), e.timeMicros());
                        robots.put(e.robotId(), robot);
                        first = true;
                    }
                    robot.bridged |= e.channel() == touchline.transport.Channel.BRIDGE;
                    String note = robot.take(e, rosReadings);
                    if (note != null) {
                        note(note);
                    }
                    if (!robot.online) {
                        robot.online = true;
                        // a bridged robot is no UDP robot: nothing is asked of it when it comes online
                        cameOnline = tellsPresence && !robot.bridged ? robot.id : Envelope.NO_ROBOT;
                    }
                }
                version++;
            }
            if (cameOnline != Envelope.NO_ROBOT) {
                for (RobotPresence p : presence) {
                    p.cameOnline(cameOnline, first);
                }
            }
        }
    }

    /** A malformed datagram from a known robot's address also counts against that robot. */
    private static void attributeMalformed(InetSocketAddress peer, Map<Integer, Robot> robots) {
        for (Robot r : robots.values()) {
            if (peer.equals(r.address)) {
                r.malformed++;
            }
        }
    }

    /**
     * A robot behind a Foxglove bridge, in the table before its first message: named {@code name},
     * at {@code peer} (its messages' peer, so a message that does not decode counts against it).
     * Its ROS 2 messages tell its pose, battery and game state ({@link RosReadings}).
     */
    public synchronized void addBridged(int id, String name, InetSocketAddress peer) {
        Robot r = robots.computeIfAbsent(id, k -> new Robot(k, Origin.LIVE, clock.nowMicros()));
        r.bridged = true;
        r.givenName = name;
        r.address = r.address == null ? peer : r.address;
        version++;
    }

    /** What the robots' ROS 2 messages are read as beyond their types (the user's mapping file). */
    public void useRosMapping(RosMapping mapping) {
        rosReadings = new RosReadings(mapping);
    }

    /** Marks robots offline whose keep-alives stopped; call a few times a second. */
    public void tick() {
        long now = clock.nowMicros();
        long replayNow = replayClock.nowMicros();
        List<Integer> wentOffline = new ArrayList<>();
        synchronized (this) {
            for (Robot r : robots.values()) {
                if (r.online && now - r.lastSeenMicros > offlineAfterMicros) {
                    r.online = false;
                    if (!r.bridged) {
                        wentOffline.add(r.id);
                    }
                    version++;
                }
            }
            for (Robot r : replayed.values()) {
                if (r.online && replayNow - r.lastSeenMicros > offlineAfterMicros) {
                    r.online = false;
                    version++;
                }
            }
        }
        for (int id : wentOffline) {
            for (RobotPresence p : presence) {
                p.wentOffline(id);
            }
        }
    }

    private void note(String text) {
        notes.add(text);
        if (notes.size() > MAX_NOTES) {
            notes.remove(0);
        }
    }

    /** Live robots by ID, then replayed robots by ID. */
    public synchronized List<RobotSnapshot> robots() {
        long now = clock.nowMicros();
        long replayNow = replayClock.nowMicros();
        List<RobotSnapshot> out = new ArrayList<>(robots.size() + replayed.size());
        for (Robot r : robots.values()) {
            out.add(r.snapshot(now));
        }
        for (Robot r : replayed.values()) {
            out.add(r.snapshot(replayNow));
        }
        return out;
    }

    /** The live robot with this ID. */
    public Optional<RobotSnapshot> robot(int id) {
        return robot(id, Origin.LIVE);
    }

    public synchronized Optional<RobotSnapshot> robot(int id, Origin origin) {
        Robot r = (origin == Origin.REPLAY ? replayed : robots).get(id);
        return r == null ? Optional.empty()
                : Optional.of(r.snapshot(origin == Origin.REPLAY ? replayClock.nowMicros() : clock.nowMicros()));
    }

    /**
     * Forgets the replayed robots and senders (the replay jumped or closed): they appear again, counted
     * afresh, with the next envelope the replay plays. Live robots are untouched.
     */
    public synchronized void forgetReplayed() {
        if (!replayed.isEmpty() || !replay.sources.isEmpty()) {
            replayed.clear();
            replay.sources.clear();
            version++;
        }
    }

    /** The frames the ROS 2 robots of one stream told (their TF trees and framed poses), by robot. */
    public synchronized Map<Integer, RobotFrames> frames(Origin origin) {
        Map<Integer, RobotFrames> out = new TreeMap<>();
        (origin == Origin.REPLAY ? replayed : robots).forEach((id, r) -> {
            RobotFrames f = r.frames();
            if (f != null) {
                out.put(id, f);
            }
        });
        return out;
    }

    public synchronized List<SourceSnapshot> sources() {
        List<SourceSnapshot> out = new ArrayList<>();
        live.sources.forEach((a, s) -> out.add(new SourceSnapshot(a, s.packets, s.malformed, s.lastError, s.lastSeen,
                Origin.LIVE)));
        replay.sources.forEach((a, s) -> out.add(new SourceSnapshot(a, s.packets, s.malformed, s.lastError,
                s.lastSeen, Origin.REPLAY)));
        out.sort(Comparator.comparing(SourceSnapshot::origin).thenComparing(s -> s.address().toString()));
        return out;
    }

    /** Anomalies worth a line for the user (a robot changing address, ...). */
    public synchronized List<String> notes() {
        return List.copyOf(notes);
    }

    /** Increases on every change; views compare it to skip work when nothing changed. */
    public synchronized long version() {
        return version;
    }
}
