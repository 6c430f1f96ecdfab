package touchline.app;

import touchline.model.DebugOptionSession;
import touchline.model.RobotRegistry;
import touchline.model.TrafficMeter;
import touchline.protocol.MessageCodec;
import touchline.protocol.MessageKinds;
import touchline.transport.EnvelopeBus;
import touchline.transport.MicrosClock;
import touchline.transport.ReliableStreamHandler;
import touchline.transport.SendGate;
import touchline.transport.SendResult;
import touchline.transport.UdpTransport;

import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;

/**
 * The application core both faces share: the Envelope stream, the UDP transport feeding it,
 * and the model listening to it. The UI and the CLI construct one Console and read from its
 * model; anything they do to data goes through here.
 */
public final class Console implements AutoCloseable {

    private final ConsoleConfig config;
    private final MicrosClock clock;
    private final MessageKinds kinds = new MessageKinds();
    private final MessageCodec codec = new MessageCodec(kinds);
    private final EnvelopeBus bus = new EnvelopeBus();
    private final RobotRegistry robots;
    private final TrafficMeter traffic;
    private final DebugOptionSession options;
    private final UdpTransport udp;
    private final ReliableStreamHandler reliable;
    private final ScheduledExecutorService ticker;
    private final touchline.model.store.ViewStores stores;

    public Console(ConsoleConfig config) {
        this(config, MicrosClock.system());
    }

    public Console(ConsoleConfig config, MicrosClock clock) {
        this(config, clock, true);
    }

    /** @param withModel false leaves the model unsubscribed (benchmarks of the bare transport) */
    public Console(ConsoleConfig config, MicrosClock clock, boolean withModel) {
        this.config = config;
        this.clock = clock;
        this.robots = new RobotRegistry(clock);
        this.traffic = new TrafficMeter(clock);
        this.reliable = new ReliableStreamHandler(bus, clock);
        this.udp = new UdpTransport(config.udp(), codec, bus, clock, reliable);
        this.options = new DebugOptionSession(udp, codec, clock);
        this.stores = new touchline.model.store.ViewStores(clock.nowMicros());
        if (withModel) {
            bus.subscribe(robots);
            bus.subscribe(traffic);
            bus.subscribe(options);
            bus.subscribe(stores);
            robots.addPresenceListener(options);
        }
        this.ticker = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "touchline-tick");
            t.setDaemon(true);
            return t;
        });
    }

    /** Binds the UDP port and starts the model's clock; returns this for chaining. */
    public Console start() throws InterruptedException {
        udp.start();
        ticker.scheduleAtFixedRate(this::tick, config.tickMillis(), config.tickMillis(), TimeUnit.MILLISECONDS);
        return this;
    }

    private void tick() {
        try {
            robots.tick();
            options.tick();
        } catch (RuntimeException e) {
            org.slf4j.LoggerFactory.getLogger(Console.class).warn("tick failed: {}", e.toString());
        }
    }

    public SendResult setOption(int robotId, String option, boolean on) {
        return options.setWanted(robotId, option, on);
    }

    public EnvelopeBus bus() { return bus; }
    public RobotRegistry robots() { return robots; }
    public DebugOptionSession options() { return options; }
    public TrafficMeter traffic() { return traffic; }
    public UdpTransport udp() { return udp; }
    public ReliableStreamHandler reliable() { return reliable; }

    /** Match mode and the like: what may go to robots right now (GameController packets aside). */
    public void setGate(SendGate gate) {
        udp.setGate(gate);
        reliable.setGate(gate);
    }
    public MessageKinds kinds() { return kinds; }
    public MessageCodec codec() { return codec; }
    public MicrosClock clock() { return clock; }
    /** The bounded stores the UI's views pull from once per frame. */
    public touchline.model.store.ViewStores stores() { return stores; }

    @Override
    public void close() {
        ticker.shutdownNow();
        udp.close();
    }
}
