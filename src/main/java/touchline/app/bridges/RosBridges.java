package touchline.app.bridges;

import touchline.app.LiveField;
import touchline.app.game.MatchMode;
import touchline.model.RobotRegistry;
import touchline.model.RosMapping;
import touchline.model.RosReadings;
import touchline.model.store.ViewStores;
import touchline.protocol.gamecontroller.GameControlData;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;
import touchline.transport.MicrosClock;
import touchline.transport.SendGate;
import touchline.transport.SendResult;
import touchline.transport.remote.Bridge;
import touchline.transport.remote.BridgeStatus;

import javax.net.ssl.SSLContext;
import java.net.InetSocketAddress;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * The team's ROS 2 robots, each behind its Foxglove bridge, as robots of this console (the use
 * case behind {@code --connect NAME=URL} and {@code --team FILE}): each bridge is a robot in
 * the Robots table from the moment it is added (numbered from {@link #FIRST_ROBOT}, apart from
 * the UDP robots' one-byte numbers), its messages enter the live stream like any robot's, and
 * the game state it reports feeds match mode like a small robot's keep-alive. Its commands
 * (parameters, publish, services) pass the console's send gate: held during play (and sent
 * when play stops), refused on a console viewing another Touchline.
 */
public final class RosBridges implements EnvelopeSink, AutoCloseable {

    public static final int FIRST_ROBOT = 1001;
    static final Duration MAX_BACKOFF = Duration.ofSeconds(5);

    private final EnvelopeSink live;
    private final RobotRegistry robots;
    private final ViewStores stores;
    private final MatchMode matchMode;
    private final MicrosClock clock;
    private final SendGate gate;
    private final List<Bridge> bridges = new CopyOnWriteArrayList<>();
    private volatile RosReadings readings = new RosReadings();

    /**
     * @param field    the live field: its robots, stores and clock; the game states its stream carries feed match mode
     * @param live     where the bridges' envelopes go (the field's live switch, paused with live listening)
     * @param gate     the console's send gate (held in play, shut on a viewing console)
     */
    public RosBridges(LiveField field, EnvelopeSink live, MatchMode matchMode, SendGate gate) {
        this.live = live;
        this.robots = field.robots();
        this.stores = field.stores();
        this.matchMode = matchMode;
        this.clock = field.clock();
        this.gate = gate;
        field.bus().subscribe(this);
    }

    /** Connects to one robot's bridge (it reconnects by itself); returns its robot number. */
    public synchronized int connect(BridgeAddress address, SSLContext tls) {
        int id = FIRST_ROBOT + bridges.size();
        robots.addBridged(id, address.name(), InetSocketAddress.createUnresolved(address.url().getHost(),
                address.url().getPort() < 0 ? 8765 : address.url().getPort()));
        bridges.add(new Bridge(address.name(), address.url(), tls, id, clock, live, gate, MAX_BACKOFF).start());
        return id;
    }

    /** Connects to every robot of a team file and reads their topics by its mapping. */
    public void connect(TeamFile team, SSLContext tls) {
        useMapping(team.mapping());
        for (BridgeAddress a : team.robots()) {
            connect(a, tls);
        }
    }

    /** What the robots' topics are read as beyond their types: the Robots table, the views and match mode. */
    public void useMapping(RosMapping mapping) {
        readings = new RosReadings(mapping);
        robots.useRosMapping(mapping);
        stores.useRosMapping(mapping);
    }

    /** Every bridge's connection, in the order added. */
    public List<BridgeStatus> statuses() {
        List<BridgeStatus> out = new ArrayList<>();
        for (Bridge b : bridges) {
            out.add(b.status());
        }
        return out;
    }

    public boolean isEmpty() {
        return bridges.isEmpty();
    }

    private Optional<Bridge> bridge(int robotId) {
        return bridges.stream().filter(b -> b.robotId() == robotId).findFirst();
    }

    /** Robot {@code robotId}'s channel {@code topic}'s own encoding and schema, or null: what a recording keeps. */
    public touchline.transport.remote.BridgedSchema schemaOf(int robotId, String topic) {
        return bridge(robotId).map(b -> b.schema(topic)).orElse(null);
    }

    /** Robot {@code robotId}'s parameters as last reported (empty for no such bridge). */
    public List<Bridge.Parameter> parameters(int robotId) {
        return bridge(robotId).map(Bridge::parameters).orElse(List.of());
    }

    /** Changes whenever a bridge reports parameter values. */
    public long parametersVersion() {
        long v = 0;
        for (Bridge b : bridges) {
            v += b.parametersVersion();
        }
        return v;
    }

    /** Asks robot {@code robotId} for its parameters again (reading passes no gate). */
    public SendResult refreshParameters(int robotId) {
        return bridge(robotId).map(Bridge::refreshParameters).orElseGet(() -> noBridge(robotId));
    }

    /** Sets one of robot {@code robotId}'s parameters; through the gate. */
    public SendResult setParameter(int robotId, String name, Object value) {
        return refused().orElseGet(() -> bridge(robotId).map(b -> b.setParameter(name, value))
                .orElseGet(() -> noBridge(robotId)));
    }

    /** Publishes one message typed as JSON on robot {@code robotId}'s {@code topic} (in CDR when the robot takes it); through the gate. */
    public SendResult publish(int robotId, String topic, String schemaName, String json) {
        return refused().orElseGet(() -> bridge(robotId).map(b -> b.publish(topic, schemaName, json))
                .orElseGet(() -> noBridge(robotId)));
    }

    /** Calls robot {@code robotId}'s {@code service} with a JSON request; through the gate. */
    public SendResult callService(int robotId, String service, String json) {
        return refused().orElseGet(() -> bridge(robotId).map(b -> b.callService(service, json))
                .orElseGet(() -> noBridge(robotId)));
    }

    /** What robot {@code robotId} answered to the latest service calls (responses and failures), oldest first. */
    public List<touchline.transport.remote.ServiceAnswer> serviceAnswers(int robotId) {
        return bridge(robotId).map(Bridge::serviceAnswers).orElse(List.of());
    }

    /** The commands held for robot {@code robotId}, in words. */
    public List<String> held(int robotId) {
        return bridge(robotId).map(Bridge::held).orElse(List.of());
    }

    /** A gate shut for good (a console viewing another Touchline) refuses; one held by play holds. */
    private Optional<SendResult> refused() {
        return gate.hold().filter(h -> !h.untilPlayStops()).map(h -> SendResult.failed(h.why()));
    }

    private static SendResult noBridge(int robotId) {
        return SendResult.failed("robot " + robotId + " is no ROS 2 robot of this console");
    }

    /** The console's tick: held commands go out once play stops. */
    public void tick() {
        for (Bridge b : bridges) {
            b.sendHeld();
        }
    }

    /** The game state a bridged robot reports feeds match mode, as a small robot's keep-alive does. */
    @Override
    public void accept(Envelope e) {
        if (e.channel() != Channel.BRIDGE || e.ros() == null || e.direction() != Direction.IN || e.replayed()) {
            return;
        }
        readings.gameState(e.kind(), e.ros()).ifPresent(state ->
                matchMode.observeReported(GameControlData.stateCode(state), e.robotId()));
    }

    @Override
    public void close() {
        for (Bridge b : bridges) {
            b.close();
        }
    }
}
