package touchline.app.game;

import touchline.game.Action;
import touchline.game.Game;
import touchline.protocol.gamecontroller.Decoded;
import touchline.protocol.gamecontroller.ReturnPacket;
import touchline.protocol.gamecontroller.ReturnPacketDecoder;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;
import touchline.transport.MicrosClock;
import touchline.transport.gamecontroller.BadPackets;
import touchline.transport.gamecontroller.MonitorService;
import touchline.transport.gamecontroller.RobotLiveness;

import java.net.InetSocketAddress;
import java.util.function.Consumer;
import java.util.function.Supplier;

/**
 * The robots' return packets to the {@link EmbeddedGameController}: each is published as a
 * GAMECONTROLLER envelope, marks its robot alive, goes on to the monitors, and a manual penalty
 * request (edge-triggered) is enqueued to the game's owner. A packet that does not decode, or
 * names a team not in the game, is counted per source, published as malformed and never applied;
 * the first of a source is told as an event.
 */
final class ReturnPackets {

    private final ReturnPacketDecoder decoder = new ReturnPacketDecoder();
    private final RobotLiveness liveness = new RobotLiveness();
    private final ManualPenaltyRequests manualRequests = new ManualPenaltyRequests();
    /** The HL game when one is refereed (robots' manual penalty requests apply to it), else null. */
    private final Game game;
    private final GameRuntime runtime;
    private final EnvelopeSink sink;
    private final MicrosClock stamps;
    private final BadPackets badPackets;
    private final Supplier<MonitorService> monitors;
    private final Consumer<String> events;

    ReturnPackets(Game game, GameRuntime runtime, EnvelopeSink sink, MicrosClock stamps, BadPackets badPackets,
                  Supplier<MonitorService> monitors, Consumer<String> events) {
        this.game = game;
        this.runtime = runtime;
        this.sink = sink;
        this.stamps = stamps;
        this.badPackets = badPackets;
        this.monitors = monitors;
        this.events = events;
    }

    RobotLiveness liveness() {
        return liveness;
    }

    void accept(byte[] data, InetSocketAddress from) {
        Decoded<ReturnPacket> decoded = decoder.decode(data);
        if (!decoded.isOk()) {
            reject(data, from, decoded.failure() + ": " + decoded.detail());
            return;
        }
        ReturnPacket p = decoded.value();
        if (!runtime.snapshot().hasTeam(p.team())) {
            reject(data, from, "team " + p.team() + " is not playing in this game");
            return;
        }
        sink.accept(new Envelope(stamps.nowMicros(), Direction.IN, Channel.GAMECONTROLLER, from, Envelope.NO_ROBOT,
                p.kind(), null, data, null));
        liveness.heard(p.team(), p.player(), runtime.now());
        MonitorService m = monitors.get();
        if (m != null) {
            m.returnPacket(from, data);
        }
        Action requested = game == null ? null : manualRequests.onMessage(p.team(), p.player(), p.message());
        if (requested != null) {
            runtime.perform(requested).thenAccept(o -> events.accept("robot " + p.team() + "/" + p.player()
                    + " asked for " + requested.describe() + ": " + (o.applied() ? "applied" : o.message())));
        }
    }

    private void reject(byte[] data, InetSocketAddress from, String reason) {
        boolean first = badPackets.count(from, reason);
        sink.accept(new Envelope(stamps.nowMicros(), Direction.IN, Channel.GAMECONTROLLER, from, Envelope.NO_ROBOT,
                "gc.return.malformed", null, data, reason));
        if (first) {
            events.accept("bad return packet from " + from.getAddress().getHostAddress() + ":" + from.getPort() + ": "
                    + reason + " (counted, not applied)");
        }
    }
}
