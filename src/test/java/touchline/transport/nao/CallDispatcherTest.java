package touchline.transport.nao;

import com.google.protobuf.InvalidProtocolBufferException;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import touchline.proto.Nao.HAWActorRPCRequest;
import touchline.proto.Nao.HAWActorRPCResponse;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;

import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import java.util.Queue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The link's turns alone: a fake wire (no sockets, no thread) and fake clocks the test moves by
 * hand, so deadlines, retries and the connection's states are checked turn by turn.
 */
class CallDispatcherTest {

    private static final long MS = TimeUnit.MILLISECONDS.toNanos(1);
    private static final long WALL_MICROS = 1_790_000_000_000_000L;

    /** A wire the test feeds: what was sent, the replies and events waiting, how often it reopened. */
    private static final class FakeWire implements LinkWire {
        final List<Long> sentIds = new ArrayList<>();
        final List<byte[]> sentPayloads = new ArrayList<>();
        final Queue<List<byte[]>> replies = new ArrayDeque<>();
        final Queue<NaoConnection.Event> events = new ArrayDeque<>();
        boolean accepting = true;
        int reopened;

        @Override
        public boolean send(long id, byte[] payload) {
            if (!accepting) {
                return false;
            }
            sentIds.add(id);
            sentPayloads.add(payload);
            return true;
        }

        @Override
        public List<byte[]> receive() {
            return replies.poll();
        }

        @Override
        public NaoConnection.Event nextEvent() {
            return events.poll();
        }

        @Override
        public void reopen() {
            reopened++;
        }

        void reply(long id, HAWActorRPCResponse response) {
            replies.add(List.of(ByteBuffer.allocate(8).putLong(id).array(), new byte[0], response.toByteArray()));
        }

        HAWActorRPCRequest request(int index) throws InvalidProtocolBufferException {
            return HAWActorRPCRequest.parseFrom(sentPayloads.get(index));
        }
    }

    private final FakeWire wire = new FakeWire();
    private final List<Envelope> envelopes = new ArrayList<>();
    private final NaoEnvelopeChannel channel = new NaoEnvelopeChannel(envelopes::add);
    private final List<ConnectionState> announced = new ArrayList<>();
    private final ConnectionWatch watch = new ConnectionWatch(false, "nao:9559");
    private long now = 1_000 * MS;
    private CallDispatcher dispatcher;

    private CallDispatcher dispatcher(String config) {
        LinkTraffic traffic = new LinkTraffic(channel, InetSocketAddress.createUnresolved("nao", 9559),
                () -> WALL_MICROS);
        dispatcher = new CallDispatcher("nao:9559", NaoLinkConfig.parse(config, "test"), wire, watch, traffic,
                () -> now, () -> WALL_MICROS);
        dispatcher.onStateChange(announced::add);
        return dispatcher;
    }

    private CompletableFuture<CallOutcome> call(String method, long timeoutMillis, boolean idempotent) {
        CompletableFuture<CallOutcome> future = new CompletableFuture<>();
        NaoCall call = NaoCall.of("Test", method);
        dispatcher.queue(new QueuedCall(call, HAWActorRPCRequest.newBuilder().setModule("Test").setMethod(method),
                timeoutMillis, idempotent, future, now));
        return future;
    }

    private void online() {
        wire.events.add(NaoConnection.Event.GREETING);
        dispatcher.turn();
    }

    @AfterEach
    void closeChannel() {
        channel.close();
    }

    @Test
    void aCallMadeWhileConnectingGoesOutWithTheGreetingCarryingItsWallClockDeadline() throws Exception {
        dispatcher("");
        CompletableFuture<CallOutcome> answer = call("get", 300, false);
        dispatcher.turn();
        assertTrue(wire.sentIds.isEmpty(), "nothing goes out before the handshake");

        wire.events.add(NaoConnection.Event.GREETING);
        now += 50 * MS;
        dispatcher.turn();

        assertEquals(List.of(ConnectionState.ONLINE), announced);
        assertEquals(1, wire.sentIds.size());
        HAWActorRPCRequest sent = wire.request(0);
        assertEquals("get", sent.getMethod());
        // 250 ms of its 300 are left: the robot drops it when later than that by the wall clock
        assertEquals(WALL_MICROS / 1000 + 250, sent.getDeadlineMillis());
        assertFalse(answer.isDone());

        Envelope out = envelopes.stream().filter(e -> e.direction() == Direction.OUT).findFirst().orElseThrow();
        assertEquals(Channel.NAO_RPC, out.channel());
        assertEquals("Test.get", out.kind());
        assertEquals(WALL_MICROS, out.timeMicros());
        assertTrue(envelopes.stream().anyMatch(e -> e.channel() == Channel.LINK_EVENT && e.kind().equals("nao.online")));
    }

    @Test
    void repliesEndTheirOwnCallsByIdInAnyOrderAndAnUnknownIdIsAStray() {
        dispatcher("");
        online();
        CompletableFuture<CallOutcome> first = call("a", 1000, false);
        CompletableFuture<CallOutcome> second = call("b", 1000, false);
        dispatcher.turn();
        assertEquals(2, wire.sentIds.size());

        wire.reply(wire.sentIds.get(1), HAWActorRPCResponse.newBuilder().setError("no such thing").build());
        wire.reply(wire.sentIds.get(0), HAWActorRPCResponse.getDefaultInstance());
        wire.reply(999, HAWActorRPCResponse.getDefaultInstance());
        dispatcher.turn();

        assertInstanceOf(CallOutcome.Done.class, first.join());
        assertEquals(new CallOutcome.Failed("no such thing"), second.join());
        NaoLink.LinkStats stats = dispatcher.stats();
        assertEquals(2, stats.sent());
        assertEquals(2, stats.replies());
        assertEquals(1, stats.stray());
        assertTrue(envelopes.stream().anyMatch(e -> e.direction() == Direction.IN && e.kind().equals("stray")));
    }

    @Test
    void anIdempotentCallIsResentUnderANewIdAtItsAttemptDeadlineAndTimesOutAfterItsRetries() {
        dispatcher("retries=1\nidempotent=Test.get\n");
        online();
        CompletableFuture<CallOutcome> answer = call("get", 100, true);
        assertEquals(now + 100 * MS, dispatcher.turn(), "the next turn is the attempt's deadline");

        now += 99 * MS;
        dispatcher.turn();
        assertEquals(1, wire.sentIds.size(), "not before its deadline");

        now += MS;
        dispatcher.turn();
        assertEquals(2, wire.sentIds.size());
        assertNotEquals(wire.sentIds.get(0), wire.sentIds.get(1));
        assertFalse(answer.isDone());

        // the first attempt's reply, late, no longer ends the call
        wire.reply(wire.sentIds.get(0), HAWActorRPCResponse.getDefaultInstance());
        now += 100 * MS;
        dispatcher.turn();
        assertEquals(new CallOutcome.TimedOut(200), answer.join());
        NaoLink.LinkStats stats = dispatcher.stats();
        assertEquals(1, stats.retried());
        assertEquals(1, stats.timeouts());
        assertEquals(1, stats.stray());
    }

    @Test
    void aCallNotIdempotentIsNeverResent() {
        dispatcher("retries=2\n");
        online();
        CompletableFuture<CallOutcome> answer = call("walk", 100, false);
        dispatcher.turn();
        now += 100 * MS;
        dispatcher.turn();
        assertEquals(1, wire.sentIds.size());
        assertEquals(new CallOutcome.TimedOut(100), answer.join());
    }

    @Test
    void aLostConnectionEndsEveryCallReopensTheWireAndFailsNewCallsAtOnce() {
        dispatcher("interval.Test.walk=500\n");
        online();
        CompletableFuture<CallOutcome> inFlight = call("get", 1000, false);
        call("walk", 1000, false);
        dispatcher.turn();
        CompletableFuture<CallOutcome> paced = call("walk", 1000, false); // waits for the walk interval
        dispatcher.turn();
        assertEquals(2, wire.sentIds.size());

        wire.events.add(NaoConnection.Event.DISCONNECTED);
        dispatcher.turn();

        assertEquals(ConnectionState.LOST, watch.state());
        assertEquals(1, wire.reopened);
        assertInstanceOf(CallOutcome.Lost.class, inFlight.join());
        assertInstanceOf(CallOutcome.Lost.class, paced.join());
        CompletableFuture<CallOutcome> late = call("get", 1000, false);
        dispatcher.turn();
        assertEquals(new CallOutcome.Lost("robot not connected"), late.join());
        assertEquals(2, wire.sentIds.size());
    }

    @Test
    void aCallWaitingForTheConnectionIsLostWhenItsTimeoutPasses() {
        dispatcher("");
        CompletableFuture<CallOutcome> answer = call("get", 150, false);
        assertEquals(now + 150 * MS, dispatcher.turn(), "the next turn is the waiting call's deadline");
        now += 149 * MS;
        dispatcher.turn();
        assertFalse(answer.isDone());
        now += MS;
        dispatcher.turn();
        assertEquals(new CallOutcome.Lost("no connection within 150 ms"), answer.join());
        assertEquals(1, dispatcher.stats().lost());
    }

    @Test
    void withNothingToWaitForTheNextTurnIsAnIdleTurn() {
        dispatcher("");
        online();
        assertEquals(now + CallDispatcher.IDLE_TURN_NANOS, dispatcher.turn());
    }

    @Test
    void aCallWithAShortTimeoutBringsTheNextTurnForwardFromTheIdleTurn() {
        dispatcher("");
        online();
        long idle = dispatcher.turn();
        assertEquals(now + CallDispatcher.IDLE_TURN_NANOS, idle, "the thread would sleep until its idle turn");
        CompletableFuture<CallOutcome> answer = new CompletableFuture<>();
        // sent on the caller's thread (LinkLoop.submit while the thread sleeps)
        dispatcher.dispatch(new QueuedCall(NaoCall.of("Test", "get"),
                HAWActorRPCRequest.newBuilder().setModule("Test").setMethod("get"), 50, false, answer, now));
        assertEquals(1, wire.sentIds.size());
        // what the caller compares with the sleeping thread's next turn (LinkLoop): earlier, so it wakes it
        assertEquals(now + 50 * MS, dispatcher.nextTurnNanos(now));
        assertTrue(dispatcher.nextTurnNanos(now) - idle < 0);
        now += 50 * MS;
        dispatcher.turn();
        assertInstanceOf(CallOutcome.TimedOut.class, answer.join());
    }

    @Test
    void aSendTheWireRefusesLosesTheCall() {
        dispatcher("");
        online();
        wire.accepting = false;
        CompletableFuture<CallOutcome> answer = call("get", 300, false);
        dispatcher.turn();
        assertEquals(new CallOutcome.Lost("no connection to send on"), answer.join());
        assertEquals(0, dispatcher.stats().sent());
    }

    @Test
    void theEndOfTheLinkEndsEveryCallWithItsReasonAndClosesTheState() {
        dispatcher("");
        online();
        CompletableFuture<CallOutcome> sent = call("get", 1000, false);
        dispatcher.turn();
        CompletableFuture<CallOutcome> queued = call("get", 1000, false);

        dispatcher.endCalls("link closed");
        dispatcher.closed("link closed");

        assertEquals(new CallOutcome.Lost("link closed"), sent.join());
        assertEquals(new CallOutcome.Lost("link closed"), queued.join());
        assertEquals(ConnectionState.CLOSED, watch.state());
        assertEquals(List.of(ConnectionState.ONLINE, ConnectionState.CLOSED), announced);
    }
}
