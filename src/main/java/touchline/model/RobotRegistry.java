package touchline.model;

import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.MicrosClock;

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
 * per-robot counters; and every sender address with its malformed datagrams. Fed by the
 * Envelope stream on the network thread, read by views and commands from any thread.
 */
public final class RobotRegistry implements touchline.transport.EnvelopeSink {

    /**
     * Keep-alives come every 200 ms in the lab but only once a second during a game (the HSL
     * 2026 rules allow a robot one debug packet per second; the firmware keeps to it in
     * READY/SET/PLAYING), so a robot is offline after three missed game-rate keep-alives. With
     * 1 s, every robot flickered offline during play.
     */
    public static final long DEFAULT_OFFLINE_AFTER_MICROS = 3_000_000;
    private static final int MAX_NOTES = 200;

    private final MicrosClock clock;
    private final long offlineAfterMicros;
    private final Map<Integer, Robot> robots = new TreeMap<>();
    private final Map<InetSocketAddress, Source> sources = new LinkedHashMap<>();
    private final List<RobotPresence> presence = new CopyOnWriteArrayList<>();
    private final List<String> notes = new ArrayList<>();
    private long version;

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
        this.clock = clock;
        this.offlineAfterMicros = offlineAfterMicros;
    }

    public void addPresenceListener(RobotPresence listener) {
        presence.add(listener);
    }

    @Override
    public void accept(Envelope e) {
        if (e.direction() != Direction.IN) {
            return;
        }
        int cameOnline = Envelope.NO_ROBOT;
        boolean first = false;
        synchronized (this) {
            Source source = null;
            if (e.peer() != null) {
                source = sources.computeIfAbsent(e.peer(), a -> new Source());
                source.packets++;
                source.lastSeen = e.timeMicros();
            }
            if (e.isMalformed() && source != null) {
                source.malformed++;
                source.lastError = e.error();
                attributeMalformed(e.peer());
            }
            if (e.robotId() >= 0 && !e.isMalformed()) {
                Robot robot = robots.get(e.robotId());
                if (robot == null) {
                    robot = new Robot(e.robotId(), e.timeMicros());
                    robots.put(e.robotId(), robot);
                    first = true;
                }
                String note = robot.take(e);
                if (note != null) {
                    note(note);
                }
                if (!robot.online) {
                    robot.online = true;
                    cameOnline = robot.id;
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

    /** A malformed datagram from a known robot's address also counts against that robot. */
    private void attributeMalformed(InetSocketAddress peer) {
        for (Robot r : robots.values()) {
            if (peer.equals(r.address)) {
                r.malformed++;
            }
        }
    }

    /** Marks robots offline whose keep-alives stopped; call a few times a second. */
    public void tick() {
        long now = clock.nowMicros();
        List<Integer> wentOffline = new ArrayList<>();
        synchronized (this) {
            for (Robot r : robots.values()) {
                if (r.online && now - r.lastSeenMicros > offlineAfterMicros) {
                    r.online = false;
                    wentOffline.add(r.id);
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

    public synchronized List<RobotSnapshot> robots() {
        long now = clock.nowMicros();
        List<RobotSnapshot> out = new ArrayList<>(robots.size());
        for (Robot r : robots.values()) {
            out.add(r.snapshot(now));
        }
        return out;
    }

    public synchronized Optional<RobotSnapshot> robot(int id) {
        Robot r = robots.get(id);
        return r == null ? Optional.empty() : Optional.of(r.snapshot(clock.nowMicros()));
    }

    public synchronized List<SourceSnapshot> sources() {
        List<SourceSnapshot> out = new ArrayList<>();
        sources.forEach((a, s) -> out.add(new SourceSnapshot(a, s.packets, s.malformed, s.lastError, s.lastSeen)));
        out.sort(Comparator.comparing(s -> s.address().toString()));
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
