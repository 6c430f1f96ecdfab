package touchline.app;

import touchline.model.DebugOptionSession;
import touchline.model.MatchDebugRule;
import touchline.model.MatchDigestUnpacker;
import touchline.model.RobotRegistry;
import touchline.model.RobotSnapshot;
import touchline.model.TrafficMeter;
import touchline.model.store.NetworkLog;
import touchline.model.store.PlotStore;
import touchline.model.store.TextLog;
import touchline.model.store.ViewStores;
import touchline.protocol.MatchDigestParts;
import touchline.protocol.MessageCodec;
import touchline.protocol.MessageKinds;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;
import touchline.transport.LiveStream;
import touchline.transport.ReplayStream;
import touchline.transport.MicrosClock;
import touchline.transport.ReliableSession;
import touchline.transport.ReliableStreamHandler;
import touchline.transport.UdpTransport;

import java.net.InetSocketAddress;
import java.time.Duration;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicLong;

/**
 * The field as this console hears it: the robots' UDP port and the Envelope stream it feeds, and
 * the read models on that stream (robots, debug options, traffic, the views' stores). What a view
 * or command reads of the field, and the reliable stream to a robot, comes from here; the other
 * services ({@link Referee}, {@link Replays}, ...) are built on top of it by {@link Console}.
 */
public final class LiveField {

    private final MicrosClock clock;
    private final MicrosClock modelClock;
    private final MicrosClock replayClock;
    private final MessageKinds kinds = new MessageKinds();
    private final MessageCodec codec = new MessageCodec(kinds);
    private final LiveStream bus = new LiveStream();
    private final ReplayStream replayStream = new ReplayStream();
    private final LiveSwitch live = new LiveSwitch(bus);
    private final RobotRegistry robots;
    private final TrafficMeter traffic;
    private final DebugOptionSession options;
    private final ViewStores stores;
    private final UdpTransport udp;
    private final ReliableStreamHandler reliable;
    private final RobotWaits robotWaits;
    /** The league's debug rule measured for every live robot heard (issue 40); the guarded profile's once a team is guarded. */
    private final MatchDebugRule matchRule;
    /** A match digest's Status and items, each as its own envelope (MatchDigestUnpacker). */
    private final MatchDigestParts digestParts = new MatchDigestParts(kinds);
    private final boolean withModel;
    /** Team messages heard (the budget guard's own socket), for {@link #transportCounts()}. */
    private final AtomicLong teamDatagramsIn = new AtomicLong();
    private final AtomicLong teamBytesIn = new AtomicLong();

    LiveField(ConsoleConfig config, MicrosClock clock, boolean withModel, ReplaySlot replay) {
        this.clock = clock;
        this.withModel = withModel;
        // The traffic meter's "now" follows a replay while one plays with live listening paused,
        // so its rates are the recording's rates.
        modelClock = () -> {
            Replay r = replay.get();
            return r != null && !live.isLive() ? r.state().positionMicros() : clock.nowMicros();
        };
        // Replayed robots are online, and their options stream, by the replay's position;
        // live robots by the wall clock, whatever a replay does.
        replayClock = () -> {
            Replay r = replay.get();
            return r != null ? r.state().positionMicros() : clock.nowMicros();
        };
        robots = new RobotRegistry(clock, replayClock, RobotRegistry.DEFAULT_OFFLINE_AFTER_MICROS);
        robotWaits = new RobotWaits(clock);
        traffic = new TrafficMeter(modelClock);
        matchRule = new MatchDebugRule(clock, MatchDebugRule.Limits.HSL_2026);
        udp = new UdpTransport(config.udp(), config.security(), codec, live, clock);
        reliable = udp.reliable();
        options = new DebugOptionSession(udp, codec, clock, replayClock);
        stores = new ViewStores(TextLog.DEFAULT_CAPACITY, PlotStore.DEFAULT_POINTS, NetworkLog.DEFAULT_CAPACITY,
                clock.nowMicros(), replay::open);
        if (withModel) {
            // the read models the views show: one per stream; the option session only on the live one.
            // A match digest's Status and items reach them as if streamed, on each stream (MatchDigestUnpacker);
            // what counts traffic or measures the rule sees the datagram only.
            bus.subscribe(unpacking(robots.live(), options, stores.live()));
            replayStream.subscribe(unpacking(robots.replay(), options.replayed(), stores.replay()));
            bus.subscribe(traffic);
            replayStream.subscribe(traffic);
            bus.subscribe(matchRule); // live only: a replay's packets are last match's
            robots.addPresenceListener(options);
            robots.addPresenceListener(robotWaits);
        }
    }

    /** {@code sinks} behind a match digest unpacker: a digest passes as it came, then each message in it as its own envelope. */
    EnvelopeSink unpacking(EnvelopeSink... sinks) {
        return new MatchDigestUnpacker(digestParts, List.of(sinks));
    }

    /** Binds the robots' UDP port. */
    void start() throws InterruptedException {
        udp.start();
    }

    /** Every 100 ms: robots online/offline, option-list retries, waiting commands. */
    void tick() {
        robots.tick();
        options.tick();
    }

    void tickWaits() {
        robotWaits.tick();
    }

    /** False: the model is not subscribed (benchmarks of the bare transport). */
    boolean withModel() { return withModel; }

    /** Where live envelopes enter the stream (paused with live listening). */
    LiveSwitch live() { return live; }

    UdpTransport udp() { return udp; }

    ReliableStreamHandler reliable() { return reliable; }

    MessageCodec codec() { return codec; }

    /** A team message heard on the budget guard's socket: counted and put into the live stream. */
    void acceptTeamMessage(Envelope e) {
        teamDatagramsIn.incrementAndGet();
        teamBytesIn.addAndGet(e.size());
        live.accept(e);
    }

    /** The live stream: what the field and this console's own sending publish (never a replay). */
    public LiveStream bus() { return bus; }
    /** The replay stream: what an open replay plays, for the read models and the faces that show it. */
    public ReplayStream replayStream() { return replayStream; }
    public RobotRegistry robots() { return robots; }
    public DebugOptionSession options() { return options; }
    public TrafficMeter traffic() { return traffic; }
    /** The debug rule measured for every live robot heard: per robot in play, datagrams per period, the biggest, warnings. */
    public MatchDebugRule matchRule() { return matchRule; }
    public MessageKinds kinds() { return kinds; }
    public MicrosClock clock() { return clock; }
    /** The traffic meter's "now": wall time, or the replay position while a replay plays with live listening paused. */
    public MicrosClock modelClock() { return modelClock; }
    /** The replay's position (wall time while none is open): the "now" of replayed robots. */
    public MicrosClock replayClock() { return replayClock; }

    /**
     * The bounded stores the UI's views pull from once per frame: the replay's while one is
     * open (opening it is asking to look at it), else the live ones. Live data keeps arriving
     * in the live stores meanwhile; both stay reachable by origin.
     */
    public ViewStores stores() { return stores; }

    /** The UDP port robots send to (the one bound: a port of 0 asked for any free one). */
    public int port() {
        return udp.localPort();
    }

    /**
     * Stops or resumes reading from the robots' socket: while stopped, datagrams wait in the
     * socket's receive buffer (beyond it the kernel drops them). Returns once applied. The ingest
     * benchmark measures how fast a filled buffer is drained with this.
     */
    public void setReading(boolean on) throws InterruptedException {
        udp.setReading(on);
    }

    /**
     * The UDP transport in use and why (epoll + recvmmsg, or the portable NIO), and where its two
     * ingest threads run, in words.
     */
    public String transportDescription() {
        return udp.description();
    }

    /** The UDP transport's counts of datagrams and bytes in and out, now. */
    public TransportCounts transportCounts() {
        return TransportCounts.of(udp.counters(), teamDatagramsIn.get(), teamBytesIn.get());
    }

    /** The version, runtime and portable fallbacks in use (the window's Help → About and status bar). */
    public RuntimeReport runtime() {
        return RuntimeReport.ofThisProcess(udp.backend()).withUdpCores(udp.cores());
    }

    /**
     * Opens (or returns) the reliable stream with a robot at {@code peer}: lossless, in-order
     * bytes both ways, gated by match mode like every command (held segments go out when play
     * stops; viewing a remote Touchline they never go).
     */
    public ReliableSession openStream(InetSocketAddress peer) {
        return reliable.open(peer);
    }

    /**
     * Waits until the live robot {@code robotId} has been heard from an address (at most
     * {@code timeout}, by the console's clock); empty if it was not.
     */
    public Optional<RobotSnapshot> waitForRobot(int robotId, Duration timeout) throws InterruptedException {
        return robotWaits.await(() -> robots.robot(robotId).filter(r -> r.address() != null), timeout.toNanos() / 1000);
    }

    /** Live listening on or paused (a replay may run beside live traffic or alone). */
    public void setLiveListening(boolean on) {
        live.setLive(on);
    }

    public boolean liveListening() {
        return live.isLive();
    }

    void close() {
        udp.close();
    }
}
